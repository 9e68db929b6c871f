// State-graph sizes on tiny maps, counted by hand.
#include "fleet_planner/model/state_graph.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/graph_search.h"
#include "fleet_planner/runtime/random.h"
#include "test_maps.h"

namespace fleet_planner {
namespace {

using test::freeMap;
using test::mapFromRows;

StateGraph build(const GridMap& map, const Footprint& f, ActionModel model = {}) {
  const ObstacleIndex obstacles(map);
  return StateGraph(map, obstacles, std::make_shared<FootprintCells>(f), model);
}

TEST(StateGraph, SingleCellRobotOnFreeThreeByThree) {
  const StateGraph g = build(freeMap(3, 3), Footprint::circle(0.4));
  EXPECT_EQ(g.numValidStates(), 36);
  // Forward: 6 of 9 cells have a cell ahead, per heading (24); two rotations per state (72).
  EXPECT_EQ(g.numEdges(), 24 + 72);
}

TEST(StateGraph, BackwardMovesAreAnOption) {
  ActionModel model;
  model.allow_backward = true;
  const StateGraph g = build(freeMap(3, 3), Footprint::circle(0.4), model);
  EXPECT_EQ(g.numEdges(), 24 + 24 + 72);
  EXPECT_TRUE(g.allows(g.id({1, 1, 0}), Action::Backward));
  EXPECT_EQ(g.pose(g.next(g.id({1, 1, 0}), Action::Backward)), (GridPose{0, 1, 0}));
}

// pose() finds the row by a multiplication: it must agree with the division for every state
// id, on every width, up to the largest id (pose() reads no map, so a small map's graph can be
// asked about any id).
TEST(StateGraph, PoseIsTheDivisionForEveryIdAndWidth) {
  Rng rng(7);
  std::vector<int> widths;
  for (int w = 1; w <= 70; ++w) widths.push_back(w);
  for (int w : {127, 128, 129, 255, 256, 257, 1000, 1023, 1024, 4099, 40000, 65535, 65536, 1 << 20}) widths.push_back(w);
  for (int w : widths) {
    const StateGraph g = build(freeMap(w, 1), Footprint::circle(0.4));
    auto expectDivision = [&](StateId s) {
      const int cell = s / kHeadings;
      ASSERT_EQ(g.pose(s), (GridPose{cell % w, cell / w, s % kHeadings})) << "width " << w << " id " << s;
    };
    for (StateId s = 0; s < 20000; ++s) expectDivision(s);
    for (StateId s = std::numeric_limits<StateId>::max(); s > std::numeric_limits<StateId>::max() - 20000; --s) expectDivision(s);
    for (int i = 0; i < 20000; ++i) expectDivision(static_cast<StateId>(rng.uniformInt(0, std::numeric_limits<StateId>::max())));
  }
}

TEST(StateGraph, BlockedCellRemovesItsStates) {
  const StateGraph g = build(mapFromRows({".....", ".....", "..@..", ".....", "....."}),
                             Footprint::circle(0.4));
  EXPECT_EQ(g.numValidStates(), 24 * 4);
  EXPECT_FALSE(g.valid(g.id({2, 2, 0})));
  EXPECT_FALSE(g.allows(g.id({1, 2, 0}), Action::Forward));
  EXPECT_TRUE(g.allows(g.id({1, 2, 2}), Action::Forward));
}

TEST(StateGraph, TwoCellBlockNeedsRoomToTurn) {
  // Block [-0.5, 1.5] x [-0.5, 0.5]: covers its cell and the one ahead; turning sweeps a plus
  // of radius 2 around its cell (see FootprintCells.BlockRotationSweep).
  const Footprint block = Footprint::block(-0.5, -0.5, 1.5, 0.5);
  const StateGraph small = build(freeMap(3, 3), block);
  EXPECT_EQ(small.numValidStates(), 6 * 4);
  EXPECT_EQ(small.numEdges(), 3 * 4);  // forward only: no room to turn anywhere
  const StateGraph g = build(freeMap(5, 5), block);
  EXPECT_EQ(g.numValidStates(), 20 * 4);
  // Forward: 3 x 5 per heading; each of the 8 turns fits at 2 x 2 cells.
  EXPECT_EQ(g.numEdges(), 15 * 4 + 8 * 4);
  EXPECT_TRUE(g.allows(g.id({1, 2, 0}), Action::RotateCcw));
  EXPECT_FALSE(g.allows(g.id({0, 2, 0}), Action::RotateCcw));
}

TEST(StateGraph, ObstacleOnlyInTheSweepBlocksTheTurn) {
  // Both end poses are free, but the front corner passes over (3, 2).
  const StateGraph g = build(mapFromRows({".....", ".....", "...@.", ".....", "....."}),
                             Footprint::block(-0.5, -0.5, 1.5, 0.5));
  const StateId s = g.id({1, 2, 0});
  EXPECT_TRUE(g.valid(s));
  EXPECT_TRUE(g.valid(g.next(s, Action::RotateCcw)));
  EXPECT_FALSE(g.allows(s, Action::RotateCcw));
}

TEST(StateGraph, PredecessorsMirrorSuccessors) {
  const StateGraph g = build(mapFromRows({"......", ".@....", "......", "....@.", "......"}),
                             Footprint::block(-0.4, -0.4, 1.2, 0.4));
  long long forward = 0, backward = 0;
  for (StateId s = 0; s < g.stateIdCount(); ++s) {
    if (!g.valid(s)) continue;
    g.forEachSuccessor(s, [&](Action a, StateId t) {
      ++forward;
      bool found = false;
      g.forEachPredecessor(t, [&](Action b, StateId p) { found |= (p == s && a == b); });
      EXPECT_TRUE(found);
    });
    g.forEachPredecessor(s, [&](Action, StateId) { ++backward; });
  }
  EXPECT_EQ(forward, g.numEdges());
  EXPECT_EQ(backward, g.numEdges());
}

TEST(StateGraph, DistancesCountActions) {
  const StateGraph g = build(freeMap(4, 1), Footprint::circle(0.4));
  const auto dist = distancesTo(g, g.id({3, 0, 0}));
  EXPECT_EQ(dist[g.id({0, 0, 0})], 3);
  EXPECT_EQ(dist[g.id({0, 0, 2})], 4);  // turn, then three moves
  EXPECT_EQ(dist[g.id({3, 0, 1})], 2);  // two quarter turns
  EXPECT_TRUE(isReachable(g, g.id({0, 0, 1}), g.id({3, 0, 0})));
  EXPECT_EQ(reachableFrom(g, g.id({0, 0, 0})).size(), 16u);
}

// The A* between two states counts what the breadth-first distances count, on lattices of 1-3
// cells with random walls, and finds nothing where they find nothing.
TEST(StateGraph, StepsBetweenTwoStatesMatchTheDistances) {
  int found = 0, none = 0;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    Rng rng(seed);
    std::vector<std::string> rows(14, std::string(18, '.'));
    for (int k = 0; k < 25; ++k) rows[rng.uniformInt(0, 13)][rng.uniformInt(0, 17)] = '@';
    ActionModel model;
    model.step = 1 + static_cast<int>(seed % 3);
    const StateGraph g = build(mapFromRows(rows), Footprint::block(-1.4, -0.6, 1.4, 0.6), model);
    auto pose = [&] {
      return GridPose{static_cast<int>(rng.uniformInt(0, 17)), static_cast<int>(rng.uniformInt(0, 13)),
                      static_cast<int>(rng.uniformInt(0, 3))};
    };
    WaySearch kept(g);
    for (int pair = 0; pair < 10; ++pair) {
      const StateId from = g.id(pose());
      if (!g.valid(from)) continue;
      // Every other target one that `from` reaches (most random ones are off its lattice).
      const std::vector<StateId> reached = reachableFrom(g, from);
      const StateId to = pair % 2 ? g.id(pose()) : reached[rng.uniformInt(0, static_cast<std::int64_t>(reached.size()) - 1)];
      if (!g.valid(to)) continue;
      long long expansions = 0;
      const int steps = stepsBetween(g, from, to, 1'000'000, expansions);
      EXPECT_EQ(steps, distancesTo(g, to)[from]) << "seed " << seed << " pair " << pair;
      // The same search kept across the pairs answers the same (its table reset between them).
      EXPECT_EQ(kept.steps(from, to, 1'000'000, expansions), steps) << "seed " << seed << " pair " << pair;
      (steps >= 0 ? found : none) += 1;
    }
  }
  EXPECT_GT(found, 50);
  EXPECT_GT(none, 20);
}

// The chessboard clearance is a lower bound of the Euclidean one, and an index built with it
// answers every placement as the exact one does: random sparse obstacles, random cell sets.
TEST(ObstacleIndex, ChessboardClearanceAnswersAsTheExactOne) {
  Rng rng(4);
  int blocked_seen = 0, free_seen = 0;
  for (int round = 0; round < 20; ++round) {
    const int w = static_cast<int>(rng.uniformInt(5, 40)), h = static_cast<int>(rng.uniformInt(5, 40));
    std::vector<std::uint8_t> cells(static_cast<std::size_t>(w) * h, 0);
    for (int k = static_cast<int>(rng.uniformInt(0, 6)); k > 0; --k)
      cells[static_cast<std::size_t>(rng.uniformInt(0, h - 1)) * w + rng.uniformInt(0, w - 1)] = 1;
    const GridMap map(w, h, cells);
    const ObstacleIndex exact(map), chessboard(map, ObstacleIndex::Clearance::Chessboard);
    const std::vector<std::int64_t> e = squaredDistanceToBlocked(map), c = squaredChessboardToBlocked(map);
    for (std::size_t i = 0; i < e.size(); ++i) ASSERT_LE(c[i], e[i]) << "round " << round << ", cell " << i;
    for (int k = 0; k < 200; ++k) {
      std::vector<Cell> offsets;
      const int r = static_cast<int>(rng.uniformInt(0, 4));
      for (int j = static_cast<int>(rng.uniformInt(1, 12)); j > 0; --j)
        offsets.push_back({static_cast<int>(rng.uniformInt(-r, r)), static_cast<int>(rng.uniformInt(-r, r))});
      const CellSet set = CellSet::fromCells(offsets);
      const Cell at{static_cast<int>(rng.uniformInt(0, w - 1)), static_cast<int>(rng.uniformInt(0, h - 1))};
      const bool b = exact.blocked(set, at);
      ASSERT_EQ(chessboard.blocked(set, at), b) << "round " << round;
      (b ? blocked_seen : free_seen) += 1;
    }
  }
  EXPECT_GT(blocked_seen, 100);
  EXPECT_GT(free_seen, 100);
}

TEST(FleetGraphs, RobotsWithEqualCellsShareAGraph) {
  const GridMap map = freeMap(8, 8);
  const FleetGraphs graphs(map, {Footprint::circle(0.9), Footprint::circle(1.4), Footprint::circle(1.6),
                                 Footprint::block(-0.5, -0.5, 1.5, 0.5), Footprint::circle(0.9)});
  EXPECT_EQ(graphs.numGraphs(), 3);
  EXPECT_EQ(graphs.graphIndex(0), graphs.graphIndex(1));
  EXPECT_EQ(graphs.graphIndex(0), graphs.graphIndex(4));
  EXPECT_NE(graphs.graphIndex(0), graphs.graphIndex(2));
  // Per heading: 6 x 6 cells for the 3 x 3 circles, 4 x 4 for r = 1.6, 7 x 8 for the block.
  EXPECT_EQ(graphs.totalStates(), 4LL * (36 + 36 + 16 + 56 + 36));
}

TEST(FleetGraphs, ThreadCountDoesNotChangeGraphs) {
  const GridMap map = mapFromRows({"..........", "..@@......", "......@...", "..........", "...@......",
                                   "..........", "........@.", ".........."});
  std::vector<Footprint> fps{Footprint::circle(0.6), Footprint::block(-1.1, -0.6, 0.7, 0.6),
                             Footprint::polygon({{1, 0}, {-1, 1}, {-1, -1}})};
  const FleetGraphs one(map, fps, {}, 1), two(map, fps, {}, 2);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(one.graph(i).numValidStates(), two.graph(i).numValidStates());
    EXPECT_EQ(one.graph(i).numEdges(), two.graph(i).numEdges());
  }
}

}  // namespace
}  // namespace fleet_planner
