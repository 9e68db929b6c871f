// The low-level search under area constraints that cut the target off from some time on: it
// must tell "no path" (or find the one before the cut) without filling space-time.
#include "fleet_planner/solvers/search/space_time_astar.h"

#include <gtest/gtest.h>

#include <iostream>
#include <limits>
#include <memory>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/runtime/random.h"

#include "fleet_planner/solvers/search/search_space.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

// A 40-cell corridor from x = 1 to the target room at x = 42; a single-cell robot needs 41 steps.
World corridorWorld() {
  std::vector<std::string> rows{std::string(45, '@'), "@" + std::string(43, '.') + "@", std::string(45, '@')};
  for (int y = 0; y < 3; ++y) rows[y][0] = '@';
  return World(mapFromRows(rows), {makeRobot("r", Footprint::circle(0.4), {1, 1, 0}, {42, 1, 0})});
}

// A 12 x 9 room with 14 random walls and one robot (a disc, or a bar when `bar`) from a random
// cell at heading 0 to a random pose; null when start and target share a cell or the robot does
// not fit at either.
std::unique_ptr<World> randomRoom(Rng& rng, bool bar) {
  std::vector<std::string> rows(9, std::string(12, '.'));
  for (int k = 0; k < 14; ++k) rows[rng.uniformInt(0, 8)][rng.uniformInt(0, 11)] = '@';
  const GridPose start{static_cast<int>(rng.uniformInt(0, 11)), static_cast<int>(rng.uniformInt(0, 8)), 0};
  const GridPose target{static_cast<int>(rng.uniformInt(0, 11)), static_cast<int>(rng.uniformInt(0, 8)),
                        static_cast<int>(rng.uniformInt(0, 3))};
  rows[start.y][start.x] = rows[target.y][target.x] = '.';
  if (start.x == target.x && start.y == target.y) return nullptr;
  const Robot robot = bar ? makeRobot("r", Footprint::block(-0.5, -0.4, 1.5, 0.4), start, target)
                          : makeRobot("r", Footprint::circle(0.4), start, target);
  try {
    return std::make_unique<World>(mapFromRows(rows), std::vector<Robot>{robot});
  } catch (const InvalidInput&) {
    return nullptr;
  }
}

// The corridor cell x = 30 is closed from `from` on; a far-away cell constraint at t = 3000
// keeps the world changing until then, so space-time up to t = 3000 is open to a blind search.
AgentConstraints closedCorridor(int from, const CellSet& cell) {
  AgentConstraints c;
  c.forbidAreaFrom(cell, {30, 1}, from);
  c.forbidCellAt({2, 1}, 3000);
  return c;
}

TEST(SpaceTimeAStar, AreaThatCutsTheTargetOffEndsTheSearchEarly) {
  const World w = corridorWorld();
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  const CellSet cell = CellSet::fromCells({{0, 0}});
  // Closed from t = 20, before the robot can pass (it reaches x = 30 at t = 29): no path. The
  // space-time volume is 43 cells x 4 headings x 3000 steps; the search must stop far sooner.
  const LowLevelResult none = spaceTimeAStar(space, 0, closedCorridor(20, cell), sub.deadline);
  EXPECT_EQ(none.outcome, LowLevelResult::Outcome::NoPath);
  EXPECT_LT(none.expansions, 20'000);
  // Closed from t = 35, after it passes: the direct path, 41 steps.
  const LowLevelResult direct = spaceTimeAStar(space, 0, closedCorridor(35, cell), sub.deadline);
  ASSERT_EQ(direct.outcome, LowLevelResult::Outcome::Found);
  EXPECT_EQ(direct.path.size(), 42u);
  EXPECT_EQ(direct.path.back(), space.target(0));
}

// The bounds prune only what cannot finish: on random rooms with random areas, cell
// constraints and cost bounds, pruning from the first expansion finds paths of the same cost
// as never pruning (or both find none).
TEST(SpaceTimeAStar, AreaBoundsNeverChangeTheCost) {
  int found = 0, none = 0;
  for (std::uint64_t seed = 1; seed <= 600; ++seed) {
    Rng rng(seed);
    const std::unique_ptr<World> w = randomRoom(rng, seed % 2 == 0);
    if (!w) continue;
    const Subproblem sub = allRobots(*w);
    const SearchSpace space(sub);
    if (space.distance(0, space.start(0)) < 0) continue;
    std::vector<CellSet> areas;
    for (int k = 0; k < 3; ++k) areas.push_back(CellSet::fromCells({{0, 0}, {1, 0}, {0, 1}, {1, 1}}));
    AgentConstraints c;
    for (int k = 0; k < 3; ++k) {
      c.forbidAreaFrom(areas[k], {static_cast<int>(rng.uniformInt(0, 11)), static_cast<int>(rng.uniformInt(0, 8))},
                       static_cast<int>(rng.uniformInt(0, 15)));
    }
    for (int k = 0; k < 6; ++k) {
      const Cell cell{static_cast<int>(rng.uniformInt(0, 11)), static_cast<int>(rng.uniformInt(0, 8))};
      const int t = static_cast<int>(rng.uniformInt(0, 60));
      if (k % 2) c.forbidCellAt(cell, t);
      else c.forbidCellDuring(cell, t);
    }
    if (seed % 3 == 0) c.requireCostAbove(static_cast<int>(rng.uniformInt(0, 40)));
    LowLevelOptions eager, never;
    eager.area_bounds_after = 0;
    never.area_bounds_after = std::numeric_limits<long long>::max();
    const LowLevelResult a = spaceTimeAStar(space, 0, c, sub.deadline, eager);
    const LowLevelResult b = spaceTimeAStar(space, 0, c, sub.deadline, never);
    ASSERT_EQ(a.outcome, b.outcome) << "seed " << seed;
    EXPECT_EQ(a.path.size(), b.path.size()) << "seed " << seed;
    EXPECT_LE(a.expansions, b.expansions) << "seed " << seed;
    (a.outcome == LowLevelResult::Outcome::Found ? found : none) += 1;
  }
  EXPECT_GE(found, 100);
  EXPECT_GE(none, 20);
  std::cout << "[ areas     ] " << found << " paths, " << none << " without\n";
}

// Two ways from (1, 3) to (19, 3): straight along row 3 (18 steps) or round by row 1 (26: four
// turns and four more moves). Row 3's cells from x = 5 to 15 conflict with somebody's path.
World twoWays() {
  return World(mapFromRows({std::string(21, '@'), "@" + std::string(19, '.') + "@",
                            "@." + std::string(17, '@') + ".@", "@" + std::string(19, '.') + "@", std::string(21, '@')}),
               {makeRobot("r", Footprint::circle(0.4), {1, 3, 0}, {19, 3, 0})});
}

int pathConflicts(const SearchSpace& space, const LowLevelResult& r, const LowLevelOptions& o) {
  int count = 0;
  for (std::size_t t = 0; t + 1 < r.path.size(); ++t)
    count += o.conflicts(r.path[t], stepAction(space.graph(0), r.path[t], r.path[t + 1]), static_cast<int>(t));
  return count;
}

TEST(SpaceTimeAStar, FocalSearchTakesTheConflictFreeWayWithinItsWeight) {
  const World w = twoWays();
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  LowLevelOptions o;
  o.conflicts = [&](StateId s, Action, int) {
    const GridPose p = space.graph(0).pose(s);
    return p.y == 3 && p.x >= 5 && p.x <= 15 ? 1 : 0;
  };
  const LowLevelResult straight = spaceTimeAStar(space, 0, {}, sub.deadline, o);
  ASSERT_EQ(straight.outcome, LowLevelResult::Outcome::Found);
  EXPECT_EQ(straight.path.size(), 19u);
  EXPECT_EQ(straight.lower_bound, 18);
  EXPECT_GT(pathConflicts(space, straight, o), 0);
  // 26 <= 1.5 x 18: round by row 1, without conflicts; the least open f then was the optimum.
  o.focal_weight = 1.5;
  const LowLevelResult round = spaceTimeAStar(space, 0, {}, sub.deadline, o);
  ASSERT_EQ(round.outcome, LowLevelResult::Outcome::Found);
  EXPECT_EQ(round.path.size(), 27u);
  EXPECT_EQ(pathConflicts(space, round, o), 0);
  EXPECT_EQ(round.lower_bound, 18);
  // 26 > 1.2 x 18: straight again.
  o.focal_weight = 1.2;
  const LowLevelResult tight = spaceTimeAStar(space, 0, {}, sub.deadline, o);
  ASSERT_EQ(tight.outcome, LowLevelResult::Outcome::Found);
  EXPECT_EQ(tight.path.size(), 19u);
}

// On random rooms under random cell constraints and random conflicts, a focal search finds a
// path exactly when A* does, at most the weight times as long, with a lower bound at most the
// optimum and at least its own cost over the weight.
TEST(SpaceTimeAStar, FocalSearchStaysWithinItsWeight) {
  int found = 0, longer = 0;
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    Rng rng(seed);
    const std::unique_ptr<World> room = randomRoom(rng, false);
    if (!room) continue;
    const World& w = *room;
    const Subproblem sub = allRobots(w);
    const SearchSpace space(sub);
    if (space.distance(0, space.start(0)) < 0) continue;
    AgentConstraints c;
    for (int k = 0; k < 8; ++k)
      c.forbidCellAt({static_cast<int>(rng.uniformInt(0, 11)), static_cast<int>(rng.uniformInt(0, 8))},
                     static_cast<int>(rng.uniformInt(1, 30)));
    std::vector<char> busy(12 * 9 * 40);
    for (char& b : busy) b = rng.uniformInt(0, 2) == 0;
    LowLevelOptions o;
    o.conflicts = [&](StateId s, Action, int t) {
      const GridPose p = space.graph(0).pose(s);
      return static_cast<int>(busy[(std::min(t, 39) * 9 + p.y) * 12 + p.x]);
    };
    const LowLevelResult exact = spaceTimeAStar(space, 0, c, sub.deadline, o);
    o.focal_weight = 1.5;
    const LowLevelResult focal = spaceTimeAStar(space, 0, c, sub.deadline, o);
    ASSERT_EQ(exact.outcome, focal.outcome) << "seed " << seed;
    if (exact.outcome != LowLevelResult::Outcome::Found) continue;
    const int best = static_cast<int>(exact.path.size()) - 1, cost = static_cast<int>(focal.path.size()) - 1;
    EXPECT_EQ(focal.path.front(), space.start(0));
    EXPECT_EQ(focal.path.back(), space.target(0));
    EXPECT_LE(cost, 1.5 * best) << "seed " << seed;
    EXPECT_LE(focal.lower_bound, best) << "seed " << seed;
    EXPECT_LE(cost, 1.5 * focal.lower_bound) << "seed " << seed;
    longer += cost > best;
    ++found;
  }
  EXPECT_GE(found, 150);
  EXPECT_GE(longer, 10);
  std::cout << "[ focal     ] " << found << " paths, " << longer << " longer than the optimum\n";
}

}  // namespace
}  // namespace fleet_planner::test
