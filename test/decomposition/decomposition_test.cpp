// The decomposition (paper: Methodology, Algorithms 1-4) on hand-made instances whose clusters
// and levels are worked out by hand, and on a thousand random instances. Every decomposition
// made here is checked by the independent legality checker (legality.h).
//
// Model reminder for the hand-made maps: one-cell robots (circle r = 0.4); per step a robot
// waits, moves one cell forward or turns +-90 degrees in place. Map rows are drawn with row
// string 0 = y 0, so "up" in the drawings is -y (heading 3) and "down" is +y (heading 2).
//
// The relations of the paper (r_s, r_t) count a state as related to a start or target when the
// robot's footprint there OR the cells swept by any edge into or out of it overlap that start
// or target. For a one-cell robot at cell c with heading h this means c itself and the cells
// directly ahead of and behind c along h. The maps below keep a free "spacer" cell between the
// starts/targets and the routes that are meant to avoid them, so that the intended relations
// are the only ones.
#include "fleet_planner/decomposition/decomposition.h"
#include "fleet_planner/decomposition/relation_graph.h"
#include "fleet_planner/decomposition/dependency_search.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "test_maps.h"
#include "test_robots.h"
#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/io/instance_generator.h"
#include "fleet_planner/runtime/random.h"
#include "fleet_planner/decomposition/legality.h"

namespace fleet_planner {
namespace {

using test::mapFromRows;

using test::dot;
using test::footprintsOf;

struct World {
  GridMap map;
  Instance instance;
  FleetGraphs graphs;
  World(GridMap m, std::vector<Robot> robots)
      : map(std::move(m)), instance{std::move(robots), ""}, graphs(map, footprintsOf(instance)) {}
  int index(const std::string& id) const {
    for (std::size_t i = 0; i < instance.robots.size(); ++i) {
      if (instance.robots[i].id == id) return static_cast<int>(i);
    }
    ADD_FAILURE() << "no robot " << id;
    return -1;
  }
};

std::vector<std::vector<int>> robotLists(const Decomposition& d) {
  std::vector<std::vector<int>> lists;
  for (const auto& s : d.subproblems) lists.push_back(s.robots);
  return lists;
}

std::string describe(const Decomposition& d) {
  std::ostringstream out;
  for (const auto& s : d.subproblems) {
    out << "{c" << s.cluster << " l" << s.level << ":";
    for (int r : s.robots) out << " " << r;
    out << "} ";
  }
  out << "steps:";
  for (const auto& s : d.steps) out << " [" << s.step << ": " << s.subproblems << " subproblems, largest " << s.largest << "]";
  return out.str();
}

// Structural checks of one decomposition, independent of legality: every robot exactly once,
// robots ascending, no empty subproblem, statistics consistent with the subproblems, each
// cluster's levels numbered 0, 1, 2, ... in solving order.
::testing::AssertionResult wellFormed(const Instance& instance, const Decomposition& d, int last_step) {
  const int n = static_cast<int>(instance.robots.size());
  std::vector<int> seen(n, 0);
  for (const auto& s : d.subproblems) {
    if (s.robots.empty()) return ::testing::AssertionFailure() << "empty subproblem: " << describe(d);
    if (!std::is_sorted(s.robots.begin(), s.robots.end()))
      return ::testing::AssertionFailure() << "robots not ascending: " << describe(d);
    for (int r : s.robots) {
      if (r < 0 || r >= n) return ::testing::AssertionFailure() << "robot index " << r << " out of range: " << describe(d);
      ++seen[r];
    }
  }
  for (int r = 0; r < n; ++r) {
    if (seen[r] != 1)
      return ::testing::AssertionFailure() << "robot " << r << " appears " << seen[r] << " times: " << describe(d);
  }
  if (!d.complete) return ::testing::AssertionFailure() << "incomplete without a deadline: " << describe(d);
  if (static_cast<int>(d.steps.size()) != last_step)
    return ::testing::AssertionFailure() << d.steps.size() << " step statistics for last_step " << last_step;
  for (int k = 0; k < last_step; ++k) {
    if (d.steps[k].step != k + 1) return ::testing::AssertionFailure() << "steps[" << k << "].step = " << d.steps[k].step;
  }
  if (n > 0 && (d.steps.back().subproblems != static_cast<int>(d.subproblems.size()) ||
                d.steps.back().largest != d.largest()))
    return ::testing::AssertionFailure() << "last step statistics do not match the subproblems: " << describe(d);
  std::vector<int> next_level;
  for (const auto& s : d.subproblems) {
    if (s.cluster < 0) return ::testing::AssertionFailure() << "negative cluster: " << describe(d);
    if (s.cluster >= static_cast<int>(next_level.size())) next_level.resize(s.cluster + 1, 0);
    if (s.level != next_level[s.cluster]++)
      return ::testing::AssertionFailure() << "levels of cluster " << s.cluster << " not 0, 1, 2, ... in order: " << describe(d);
  }
  if (last_step <= 2) {
    for (int c : next_level) {
      if (c > 1) return ::testing::AssertionFailure() << "levels before step 3: " << describe(d);
    }
  }
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult legal(const Instance& instance, const FleetGraphs& graphs, const Decomposition& d) {
  const LegalityReport report = checkLegality(instance, graphs, robotLists(d));
  if (report.legal) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "illegal decomposition: " << report.message << "\n  " << describe(d);
}

// Decomposes with `last_step`, asserting the result well formed and legal.
Decomposition decomposeChecked(const World& w, int last_step, bool peel_levels = true) {
  DecompositionOptions options;
  options.last_step = last_step;
  options.peel_levels = peel_levels;
  const Decomposition d = decompose(w.instance, w.graphs, options);
  EXPECT_TRUE(wellFormed(w.instance, d, last_step)) << "last_step " << last_step;
  EXPECT_TRUE(legal(w.instance, w.graphs, d)) << "last_step " << last_step;
  return d;
}

// ---------------------------------------------------------------------------------------------
// Figure 1 of the paper, exactly as in its caption, on the plus-shaped 3 x 3 map. The caption
// gives cells only; the headings are chosen along each robot's line of travel, so nobody needs
// to turn. Under this model the instance behaves as the caption says: no robot's states are
// related to the other's start or target cells (a1 only faces -y on column x = 1, a2 +x on row y = 1).

GridMap plusMap() { return mapFromRows({"@.@", "...", "@.@"}); }

TEST(Decomposition, FigureOneATwoClusters) {
  // a1 (1,2) -> (1,0), a2 (0,1) -> (2,1): both cross the centre, neither needs the other's
  // start or target: two clusters, solvable in either order.
  const World w(plusMap(), {dot("a1", {1, 2, 3}, {1, 0, 3}), dot("a2", {0, 1, 0}, {2, 1, 0})});
  const Decomposition d = decomposeChecked(w, 4);
  ASSERT_EQ(d.subproblems.size(), 2u) << describe(d);
  EXPECT_EQ(d.subproblems[0].robots.size(), 1u);
  EXPECT_EQ(d.subproblems[1].robots.size(), 1u);
  EXPECT_NE(d.subproblems[0].cluster, d.subproblems[1].cluster) << describe(d);
  EXPECT_EQ(d.subproblems[0].level, 0);
  EXPECT_EQ(d.subproblems[1].level, 0);
  // Clusters have no order: the reversed list is legal too.
  EXPECT_TRUE(checkLegality(w.instance, w.graphs, {{1}, {0}}).legal);
  EXPECT_TRUE(checkLegality(w.instance, w.graphs, {{0}, {1}}).legal);
  // Already after step 1.
  EXPECT_EQ(decomposeChecked(w, 1).subproblems.size(), 2u);
}

TEST(Decomposition, FigureOneBTwoLevelsA2First) {
  // a1 (1,2) -> (1,1) needs nothing of a2; a2 (0,1) -> (2,1) must cross a1's target: one
  // cluster, two levels, a2's first.
  const World w(plusMap(), {dot("a1", {1, 2, 3}, {1, 1, 3}), dot("a2", {0, 1, 0}, {2, 1, 0})});
  const Decomposition clusters = decomposeChecked(w, 2);
  ASSERT_EQ(clusters.subproblems.size(), 1u) << describe(clusters);
  const Decomposition d = decomposeChecked(w, 4);
  ASSERT_EQ(d.subproblems.size(), 2u) << describe(d);
  EXPECT_EQ(d.subproblems[0].robots, std::vector<int>{1}) << describe(d);
  EXPECT_EQ(d.subproblems[1].robots, std::vector<int>{0}) << describe(d);
  EXPECT_EQ(d.subproblems[0].cluster, d.subproblems[1].cluster);
  EXPECT_EQ(d.subproblems[0].level, 0);
  EXPECT_EQ(d.subproblems[1].level, 1);
  // The other order is not legal: the checker agrees that the order matters.
  EXPECT_FALSE(checkLegality(w.instance, w.graphs, {{0}, {1}}).legal);
  // Step 3 alone already orders them.
  EXPECT_EQ(robotLists(decomposeChecked(w, 3)), (std::vector<std::vector<int>>{{1}, {0}}));
}

// ---------------------------------------------------------------------------------------------
// Cluster bipartition (step 2). A ring with a short bottom route and a long top route between
// A's start (1,4) and target (9,4); a spur (10..12,4) beyond A's target.
//
//   x: 0123456789012
//   y0 @.........@@@     P starts at (4,0), Q at (6,0)
//   y1 @.@@@@@@@.@@@
//   y2 @.@@@@@@@.@@@
//   y3 @.@@@@@@@.@@@
//   y4 @............     A (1,4) -> (9,4); X starts at (5,4); P ends at (11,4), Q at (12,4)
//   y5 @@@@@.@@@@@@@     X ends at (5,5)
//
// A: the bottom route crosses X's start (related to X only), the top route crosses P's and Q's
//    starts. Step 1 takes the path related to the fewest starts/targets (and the shortest): the
//    bottom one, so A is relevant to X.
// X: one step down, related to nobody.
// P, Q: must cross A's target to reach the spur (and Q must cross P's target).
// Step 1: relevance A-X, A-P, A-Q, P-Q: one cluster of 4.
// Step 2: A, P, Q are unavoidably related (P and Q cannot avoid A; Q cannot avoid P); A can
// avoid X by the top route; X avoids them all: clusters {A, P, Q} and {X}.

World clusterSplitWorld() {
  return World(mapFromRows({"@.........@@@",
                            "@.@@@@@@@.@@@",
                            "@.@@@@@@@.@@@",
                            "@.@@@@@@@.@@@",
                            "@............",
                            "@@@@@.@@@@@@@"}),
               {dot("A", {1, 4, 2}, {9, 4, 0}), dot("X", {5, 4, 2}, {5, 5, 2}), dot("P", {4, 0, 0}, {11, 4, 0}),
                dot("Q", {6, 0, 0}, {12, 4, 0})});
}

TEST(Decomposition, ClusterBipartitionSplitsAnInitialCluster) {
  const World w = clusterSplitWorld();
  const Decomposition d = decomposeChecked(w, 2);
  ASSERT_EQ(d.steps.size(), 2u);
  EXPECT_EQ(d.steps[0].subproblems, 1) << describe(d);
  EXPECT_EQ(d.steps[0].largest, 4) << describe(d);
  EXPECT_EQ(d.steps[1].subproblems, 2) << describe(d);
  EXPECT_EQ(d.steps[1].largest, 3) << describe(d);
  const std::vector<std::vector<int>> lists = robotLists(d);
  const std::set<std::vector<int>> parts(lists.begin(), lists.end());
  const std::vector<int> apq{w.index("A"), w.index("P"), w.index("Q")};
  EXPECT_EQ(parts, (std::set<std::vector<int>>{apq, {w.index("X")}})) << describe(d);
  EXPECT_LT(d.steps[1].largest, d.steps[0].largest);
  // The later steps keep it legal (checked inside) and never make it worse.
  for (int step = 3; step <= 4; ++step) EXPECT_LE(decomposeChecked(w, step).largest(), 3);
  // Step 1 alone: the one cluster.
  EXPECT_EQ(decomposeChecked(w, 1).largest(), 4);
}

// ---------------------------------------------------------------------------------------------
// Level bipartition (step 4). The same ring, 10 wide, with a dead end (0,2) off the left side.
//
//   x: 0123456789
//   y0 @.........     C starts at (4,0)
//   y1 @.@@@@@@@.
//   y2 ..@@@@@@@.     C ends at (0,2); B ends at (1,2)
//   y3 @.@@@@@@@.
//   y4 @.........     A (1,4) -> (9,4); B starts at (3,4)
//
// A: bottom route crosses B's start; top route crosses B's target and C's start.
// B: (3,4) -> (1,2): through A's start (short), or all the way round through A's target and
//    C's start (long).
// C: must cross B's target (1,2) to reach its dead end (0,2); nothing else.
// Clusters: A and B cannot avoid each other, C cannot avoid B: one cluster of 3 (also after
// step 2).
// Step 3 (fewest relations): A takes the bottom route (B before A), B passes A's start (A before
// B): a cycle, so one level {A, B}; C passes B's target (C before B): level {C} first.
// Step 4: A can take the top route instead (related to B's target and C's start: A before B,
// after C), or B the long one: {A, B} splits. Three levels of one robot, C first.

World levelSplitWorld() {
  return World(mapFromRows({"@.........",
                            "@.@@@@@@@.",
                            "..@@@@@@@.",
                            "@.@@@@@@@.",
                            "@........."}),
               {dot("A", {1, 4, 2}, {9, 4, 0}), dot("B", {3, 4, 1}, {1, 2, 3}), dot("C", {4, 0, 1}, {0, 2, 1})});
}

TEST(Decomposition, LevelBipartitionSplitsAnInitialLevel) {
  const World w = levelSplitWorld();
  for (bool peel : {false, true}) {
    SCOPED_TRACE(peel ? "with peeling" : "Algorithm 4 alone");
    const Decomposition d = decomposeChecked(w, 4, peel);
    ASSERT_EQ(d.steps.size(), 4u);
    EXPECT_EQ(d.steps[1].subproblems, 1) << describe(d);
    EXPECT_EQ(d.steps[1].largest, 3) << describe(d);
    EXPECT_EQ(d.steps[2].subproblems, 2) << describe(d);
    EXPECT_EQ(d.steps[2].largest, 2) << describe(d);
    EXPECT_EQ(d.steps[3].subproblems, 3) << describe(d);
    EXPECT_EQ(d.steps[3].largest, 1) << describe(d);
    EXPECT_LT(d.steps[3].largest, d.steps[2].largest);
    ASSERT_EQ(d.subproblems.size(), 3u);
    EXPECT_EQ(d.subproblems[0].robots, std::vector<int>{w.index("C")}) << describe(d);
    for (const auto& s : d.subproblems) EXPECT_EQ(s.cluster, d.subproblems[0].cluster);
  }
  // Step 3 alone: C first, then A and B together.
  const Decomposition three = decomposeChecked(w, 3);
  EXPECT_EQ(robotLists(three), (std::vector<std::vector<int>>{{w.index("C")}, {w.index("A"), w.index("B")}}))
      << describe(three);
}

// ---------------------------------------------------------------------------------------------
// Contract details of the header.

TEST(Decomposition, UnreachableTargetThrowsNamingTheRobot) {
  const World w(mapFromRows({"..@.."}), {dot("ok", {0, 0, 0}, {1, 0, 0}), dot("stuck", {3, 0, 0}, {0, 0, 1})});
  try {
    decompose(w.instance, w.graphs, {});
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("'stuck'"), std::string::npos) << e.what();
  }
}

TEST(Decomposition, NoRobotsNoSubproblems) {
  const World w(mapFromRows({"..."}), {});
  const Decomposition d = decompose(w.instance, w.graphs, {});
  EXPECT_TRUE(d.subproblems.empty());
  EXPECT_EQ(d.largest(), 0);
  EXPECT_EQ(d.rate(0), 0.0);
}

TEST(Decomposition, ExpiredDeadlineGivesTheWholeFleetAsOneLegalSubproblem) {
  // decomposition.h: when the deadline cuts it short, complete = false and the result is still
  // legal. A deadline that has passed before the relation graphs are built (seconds of work on a
  // large map: the stress sweep measured 0.3 s of CPU past a 0.1 s limit) stops before them and
  // gives the whole fleet as one subproblem, without any step. Cluster-split world: step 1 gives
  // one cluster that step 2 would split.
  const World w = clusterSplitWorld();
  const Decomposition full = decompose(w.instance, w.graphs, {});
  const Decomposition d = decompose(w.instance, w.graphs, {}, Deadline::in(0));
  EXPECT_TRUE(full.complete);
  EXPECT_FALSE(d.complete);
  EXPECT_TRUE(d.steps.empty()) << describe(d);
  ASSERT_EQ(d.subproblems.size(), 1u) << describe(d);
  EXPECT_EQ(d.largest(), static_cast<int>(w.instance.robots.size()));
  EXPECT_GT(d.largest(), full.largest()) << describe(d);
  EXPECT_TRUE(legal(w.instance, w.graphs, d));
}

TEST(Decomposition, RelationGraphsStopAtTheDeadline) {
  const World w = clusterSplitWorld();
  for (const RelationGraph& r : buildRelationGraphs(w.instance, w.graphs, 1, Deadline::in(0))) {
    EXPECT_EQ(r.graph, nullptr);
  }
  for (const RelationGraph& r : buildRelationGraphs(w.instance, w.graphs, 2, Deadline::in(60))) {
    EXPECT_NE(r.graph, nullptr);
  }
}

// On a lattice of step 2 one graph serves robots on different lattices (offsets): the
// component graph covers each robot's own. Dot a (odd x) drives along a corridor past the
// start and target of dot b (even x), which drives along it too.
TEST(Decomposition, RelationGraphsOnALatticeCoverEveryRobotsOwnLattice) {
  const GridMap map = mapFromRows({"@@@@@@@@@@@@@", ".............", "@@@@@@@@@@@@@"});
  Instance instance{{dot("a", {1, 1, 0}, {11, 1, 0}), dot("b", {6, 1, 0}, {8, 1, 0})}, ""};
  const FleetGraphs graphs(map, footprintsOf(instance), ActionModel{false, 2});
  ASSERT_EQ(graphs.graphIndex(0), graphs.graphIndex(1));
  const std::vector<RelationGraph> relations = buildRelationGraphs(instance, graphs, 1, Deadline::in(60));
  for (const RelationGraph& r : relations) {
    ASSERT_NE(r.graph, nullptr);
    EXPECT_GE(r.start, 0) << "robot " << r.robot;
    EXPECT_GE(r.target, 0) << "robot " << r.robot;
    EXPECT_TRUE(pathExists(r, SatFilter{})) << "robot " << r.robot;
  }
  // a's way passes b's start (SAT 2) and b's target (SAT 3); b's passes neither of a's ends.
  SatFilter without_b_start;
  without_b_start.avoided = {0, 0, 1, 0};
  EXPECT_FALSE(pathExists(relations[0], without_b_start));
  EXPECT_EQ(searchPathSats(relations[0], SatFilter{}), (std::vector<int>{2, 3}));
  EXPECT_EQ(searchPathSats(relations[1], SatFilter{}), std::vector<int>{});
}

// Two dots trading ends of a corridor cannot go one after the other (each one's target is the
// other's start); a third on a row of its own can go before or after either.
TEST(Decomposition, EntangledPairsNameTheRobotsThatNoOrderServes) {
  const World w(mapFromRows({".......", "@@@@@@@", "......."}),
                {dot("A", {0, 0, 0}, {6, 0, 0}), dot("B", {6, 0, 1}, {0, 0, 1}),
                 dot("C", {0, 2, 0}, {6, 2, 0})});
  const Decomposition d = decomposeChecked(w, 4);
  EXPECT_TRUE(d.pairs_complete);
  const std::vector<std::pair<int, int>> expected{{w.index("A"), w.index("B")}};
  EXPECT_EQ(d.entangled_pairs, expected) << describe(d);
}

TEST(Decomposition, RateIsLargestOverRobots) {
  const World w = clusterSplitWorld();
  const Decomposition d = decomposeChecked(w, 2);
  EXPECT_DOUBLE_EQ(d.rate(4), 3.0 / 4.0);
}

// ---------------------------------------------------------------------------------------------
// Random instances: small maps with a few obstacle cells, 2-8 robots of up to 3 x 3 cells.

GridMap randomMap(std::uint64_t seed) {
  Rng rng(seed * 7919 + 17);
  const int width = static_cast<int>(rng.uniformInt(12, 20));
  const int height = static_cast<int>(rng.uniformInt(12, 20));
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(width) * height, 0);
  const auto obstacles = rng.uniformInt(0, width * height / 8);
  for (std::int64_t k = 0; k < obstacles; ++k) cells[rng.uniformInt(0, width * height - 1)] = 1;
  return GridMap(width, height, cells);
}

// 2-8 robots of up to 3 x 3 cells on `map`; none if the generator cannot place them.
std::optional<Instance> randomInstance(const GridMap& map, std::uint64_t seed) {
  GeneratorOptions options;
  options.seed = seed;
  options.robots = 2 + static_cast<int>(seed % 7);
  options.max_size = 1.0;
  options.attempts_per_robot = 500;
  try {
    return generateInstance(map, options);
  } catch (const InvalidInput&) {
    return std::nullopt;
  }
}

bool sameSubproblems(const Decomposition& a, const Decomposition& b) {
  if (a.subproblems.size() != b.subproblems.size()) return false;
  for (std::size_t k = 0; k < a.subproblems.size(); ++k) {
    const auto &x = a.subproblems[k], &y = b.subproblems[k];
    if (x.robots != y.robots || x.cluster != y.cluster || x.level != y.level) return false;
  }
  if (a.steps.size() != b.steps.size()) return false;
  for (std::size_t k = 0; k < a.steps.size(); ++k) {
    if (a.steps[k].subproblems != b.steps[k].subproblems || a.steps[k].largest != b.steps[k].largest) return false;
  }
  return true;
}

// Every part of `fine` lies inside one part of `coarse`.
bool refines(const Decomposition& fine, const Decomposition& coarse, int n) {
  std::vector<int> part(n, -1);
  for (std::size_t k = 0; k < coarse.subproblems.size(); ++k) {
    for (int r : coarse.subproblems[k].robots) part[r] = static_cast<int>(k);
  }
  for (const auto& s : fine.subproblems) {
    for (int r : s.robots) {
      if (part[r] != part[s.robots.front()]) return false;
    }
  }
  return true;
}

// pathExists answers the existence queries of the decomposition: it must agree with the ranked
// search on whether a path exists, for any filter, and the path it reports must be one.
TEST(DependencySearch, PathExistsAgreesWithTheRankedSearch) {
  int found = 0, none = 0;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const GridMap map = randomMap(seed);
    const std::optional<Instance> made = randomInstance(map, seed);
    if (!made) continue;
    const Instance& instance = *made;
    const FleetGraphs graphs(map, footprintsOf(instance));
    const std::vector<RelationGraph> relations = buildRelationGraphs(instance, graphs, 1, Deadline::in(60));
    const int sats = 2 * static_cast<int>(instance.robots.size());
    Rng rng(seed);
    for (const RelationGraph& r : relations) {
      for (int round = 0; round < 20; ++round) {
        SatFilter f;
        // Empty masks (no restriction) now and then; otherwise random ones.
        if (round % 4 != 0) {
          f.allowed.resize(sats);
          for (char& a : f.allowed) a = rng.uniform01() < 0.8;
        }
        if (round % 3 != 0) {
          f.avoided.resize(sats);
          for (char& a : f.avoided) a = rng.uniform01() < 0.3;
        }
        const bool ranked = searchPathSats(r, f).has_value();
        std::vector<int> witness;
        ASSERT_EQ(pathExists(r, f, &witness), ranked) << "seed " << seed << ", robot " << r.robot << ", round " << round;
        (ranked ? found : none) += 1;
        if (!ranked) continue;
        // The witness (what the decomposition remembers to skip later searches) names every SAT
        // of the path found: each passes the filter, and allowing only them still leaves a path.
        for (int s : witness) ASSERT_TRUE(f.passes(s)) << "seed " << seed << ", robot " << r.robot << ", SAT " << s;
        SatFilter only;
        only.allowed.assign(sats, 0);
        for (int s : witness) only.allowed[s] = 1;
        ASSERT_TRUE(pathExists(r, only)) << "seed " << seed << ", robot " << r.robot << ", round " << round;
      }
    }
  }
  EXPECT_GT(found, 1000);
  EXPECT_GT(none, 1000);
}

// Whether robots a and b of `instance` can go one after the other, a first, each alone on the
// map: the independent legality checker on the two of them as two subproblems.
bool canGoFirst(const GridMap& map, const Instance& instance, int a, int b) {
  Instance pair;
  pair.robots = {instance.robots[a], instance.robots[b]};
  const FleetGraphs graphs(map, footprintsOf(pair));
  return checkLegality(pair, graphs, {{0}, {1}}).legal;
}

// Every pair of one subproblem that can go one after the other in neither order, by the
// independent legality checker, is an entangled pair; pairs of two subproblems always can. The
// list may hold a few pairs that can (the relations are conservative), not most of them.
TEST(Decomposition, EntangledPairsHoldEveryPairThatNoOrderServes) {
  int entangled = 0, orderable = 0, orderable_listed = 0, across = 0;
  for (std::uint64_t seed = 0; seed < 400; ++seed) {
    const GridMap map = randomMap(seed);
    const std::optional<Instance> made = randomInstance(map, seed);
    if (!made) continue;
    const FleetGraphs graphs(map, footprintsOf(*made));
    const Decomposition d = decompose(*made, graphs, {});
    ASSERT_TRUE(d.pairs_complete);
    const std::set<std::pair<int, int>> listed(d.entangled_pairs.begin(), d.entangled_pairs.end());
    ASSERT_EQ(listed.size(), d.entangled_pairs.size())
        << "seed " << seed << ": a pair listed twice";
    std::vector<int> part(made->robots.size());
    for (std::size_t k = 0; k < d.subproblems.size(); ++k) {
      for (int r : d.subproblems[k].robots) part[r] = static_cast<int>(k);
    }
    for (int a = 0; a < static_cast<int>(made->robots.size()); ++a) {
      for (int b = a + 1; b < static_cast<int>(made->robots.size()); ++b) {
        const bool no_order = !canGoFirst(map, *made, a, b) && !canGoFirst(map, *made, b, a);
        if (part[a] != part[b]) {
          ++across;
          EXPECT_FALSE(no_order) << "seed " << seed << ": robots " << a << " and " << b
                                 << " of two subproblems";
          EXPECT_FALSE(listed.count({a, b})) << "seed " << seed << ": robots " << a << " and " << b;
          continue;
        }
        (no_order ? entangled : orderable) += 1;
        if (!no_order) {
          orderable_listed += static_cast<int>(listed.count({a, b}));
          continue;
        }
        EXPECT_TRUE(listed.count({a, b}))
            << "seed " << seed << ": robots " << a << " and " << b << "\n  " << describe(d);
      }
    }
  }
  // Both kinds of pair of one subproblem occur, or the test pins little.
  EXPECT_GT(entangled, 20);
  EXPECT_GT(orderable, 20);
  EXPECT_GT(across, 100);
  EXPECT_LT(orderable_listed, orderable / 2);
  std::cout << "[ entangled ] " << entangled << " pairs of one subproblem that no order serves, "
            << orderable << " that one does (" << orderable_listed << " listed), " << across
            << " across subproblems\n";
}

TEST(Decomposition, RandomInstancesLegalDeterministicAndPareto) {
  const auto begin = std::chrono::steady_clock::now();
  constexpr int kInstances = 1000;
  int made = 0, skipped = 0, pareto_failures = 0, split_any = 0;
  int improved_by[5] = {0, 0, 0, 0, 0};  // instances where step k shrank the largest subproblem
  std::uint64_t seed = 0;
  for (; made < kInstances && seed < 3 * kInstances; ++seed) {
    const GridMap map = randomMap(seed);
    const std::optional<Instance> generated = randomInstance(map, seed);
    if (!generated) {
      ++skipped;
      continue;
    }
    const Instance& instance = *generated;
    ++made;
    const int n = static_cast<int>(instance.robots.size());
    const FleetGraphs graphs(map, footprintsOf(instance));
    std::vector<Decomposition> by_step;
    for (int step = 1; step <= 4; ++step) {
      DecompositionOptions o;
      o.last_step = step;
      const Decomposition d = decompose(instance, graphs, o);
      ASSERT_TRUE(wellFormed(instance, d, step)) << "seed " << seed << " last_step " << step;
      ASSERT_TRUE(legal(instance, graphs, d)) << "seed " << seed << " last_step " << step;
      const Decomposition again = decompose(instance, graphs, o);
      ASSERT_TRUE(sameSubproblems(d, again)) << "seed " << seed << " last_step " << step << "\n  " << describe(d)
                                             << "\n  " << describe(again);
      by_step.push_back(d);
    }
    DecompositionOptions two_threads;
    two_threads.threads = 2;
    ASSERT_TRUE(sameSubproblems(by_step[3], decompose(instance, graphs, two_threads))) << "seed " << seed << ": threads";
    // Algorithm 4 alone (no peeling): legal too, and still a refinement of step 3.
    DecompositionOptions paper_only;
    paper_only.peel_levels = false;
    const Decomposition plain = decompose(instance, graphs, paper_only);
    ASSERT_TRUE(wellFormed(instance, plain, 4)) << "seed " << seed << " without peeling";
    ASSERT_TRUE(legal(instance, graphs, plain)) << "seed " << seed << " without peeling";
    EXPECT_TRUE(refines(plain, by_step[2], n)) << "seed " << seed << " without peeling\n  " << describe(by_step[2])
                                               << "\n  " << describe(plain);
    EXPECT_LE(plain.largest(), by_step[2].largest()) << "seed " << seed << " without peeling";
    for (int k = 1; k < 4; ++k) {
      // Running more steps repeats the earlier ones: the statistics agree.
      for (int j = 0; j < k; ++j) {
        EXPECT_EQ(by_step[k].steps[j].largest, by_step[j].steps[j].largest) << "seed " << seed;
        EXPECT_EQ(by_step[k].steps[j].subproblems, by_step[j].steps[j].subproblems) << "seed " << seed;
      }
      // Pareto: a step never makes the largest subproblem larger, and only splits subproblems.
      const bool pareto = by_step[k].largest() <= by_step[k - 1].largest() &&
                          by_step[3].steps[k].largest <= by_step[3].steps[k - 1].largest;
      if (!pareto) ++pareto_failures;
      if (by_step[3].steps[k].largest < by_step[3].steps[k - 1].largest) ++improved_by[k + 1];
      EXPECT_TRUE(pareto) << "seed " << seed << ": step " << k + 1 << " made the largest subproblem larger\n  "
                          << describe(by_step[k - 1]) << "\n  " << describe(by_step[k]);
      EXPECT_TRUE(refines(by_step[k], by_step[k - 1], n))
          << "seed " << seed << ": step " << k + 1 << " does not refine step " << k << "\n  " << describe(by_step[k - 1])
          << "\n  " << describe(by_step[k]);
    }
    if (by_step[3].largest() < by_step[0].largest()) ++split_any;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  EXPECT_EQ(made, kInstances) << "only " << made << " instances from " << seed << " seeds";
  EXPECT_EQ(pareto_failures, 0);
  // The steps after the first must matter on some of these instances, or the test pins little.
  EXPECT_GT(split_any, 0);
  for (int k = 2; k <= 4; ++k) EXPECT_GT(improved_by[k], 0) << "step " << k << " never shrank the largest subproblem";
  std::cout << "[ random    ] " << made << " instances, " << skipped << " seeds skipped (generator), " << split_any
            << " improved by steps 2-4 (step 2: " << improved_by[2] << ", step 3: " << improved_by[3]
            << ", step 4: " << improved_by[4] << "), " << seconds << " s\n";
}

}  // namespace
}  // namespace fleet_planner
