// Distance tables (distance_table.h): 2-byte storage gives back every distance it was given,
// copied or filled in a search's order; a search space builds them alike on one thread or
// several, and they are its graphs' distances.
#include "fleet_planner/solvers/search/distance_table.h"
#include "fleet_planner/model/graph_search.h"
#include "fleet_planner/solvers/search/search_space.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner {
namespace {

void expectSame(const DistanceTable& table, const std::vector<std::int32_t>& steps) {
  for (std::size_t s = 0; s < steps.size(); ++s)
    ASSERT_EQ(table[static_cast<StateId>(s)], steps[s]) << "state " << s;
}

TEST(DistanceTable, ShortDistancesTakeTwoBytesAndComeBackExactly) {
  const std::vector<std::int32_t> steps{0, 1, -1, 7, 65534, -1, 300};
  DistanceTable table;
  table.assign(steps);
  EXPECT_EQ(table.bytesPerState(), 2);
  expectSame(table, steps);
}

TEST(DistanceTable, ADistanceOf65535StepsOrMoreTakesFourBytes) {
  const std::vector<std::int32_t> steps{0, -1, 65535, 70000, 12};
  DistanceTable table;
  table.assign(steps);
  EXPECT_EQ(table.bytesPerState(), 4);
  expectSame(table, steps);
  // Assigned again with short distances, it goes back to two bytes.
  const std::vector<std::int32_t> short_steps{3, 2, 1, 0, -1};
  table.assign(short_steps);
  EXPECT_EQ(table.bytesPerState(), 2);
  expectSame(table, short_steps);
}

// Filled as a breadth-first search fills it (distances in order), the table gives back what a
// copy of the same distances gives, also when a distance reaches 65,535 steps on the way and
// the table widens to four bytes.
TEST(DistanceTable, AFillInSearchOrderGivesWhatACopyGives) {
  for (const int far : {300, 65534, 65535, 70000}) {
    std::vector<std::int32_t> steps(12, -1);
    const std::vector<std::pair<StateId, int>> order{{4, 0}, {9, 1}, {0, 1}, {2, 7}, {11, far - 1}, {5, far}, {7, far + 1}};
    DistanceTable filled;
    filled.reset(steps.size());
    for (const auto& [s, d] : order) {
      EXPECT_FALSE(filled.reached(s));
      filled.set(s, d);
      EXPECT_TRUE(filled.reached(s));
      steps[s] = d;
    }
    DistanceTable copied;
    copied.assign(steps);
    EXPECT_EQ(filled.bytesPerState(), copied.bytesPerState()) << "farthest " << far + 1;
    expectSame(filled, steps);
  }
}

}  // namespace
}  // namespace fleet_planner

namespace fleet_planner::test {
namespace {

// With nothing else on the map, a search space's tables are the distances of the robot's own
// graph to its target (graph_search.h's distancesTo), state by state, around walls.
TEST(SearchSpaceDistances, TheTablesAreTheGraphsDistances) {
  const GridMap map = mapFromRows({"..........",
                                   "..@@@@@...",
                                   "......@...",
                                   ".@@@..@...",
                                   "..........",
                                   "....@@@@@."});
  const std::vector<Robot> robots = {dot("r0", {0, 0, 0}, {9, 5, 2}), dot("r1", {5, 2, 1}, {0, 4, 3}),
                                     dot("r2", {9, 0, 2}, {2, 2, 0})};
  const World w(map, robots);
  const SearchSpace space(allRobots(w));
  ASSERT_TRUE(space.problem().empty()) << space.problem();
  int reached = 0;
  for (int r = 0; r < space.numAgents(); ++r) {
    const std::vector<std::int32_t> expected = distancesTo(space.graph(r), space.target(r));
    for (StateId s = 0; s < space.graph(r).stateIdCount(); ++s) {
      ASSERT_EQ(space.distance(r, s), expected[s]) << "robot " << r << ", state " << s;
      reached += expected[s] > 0;
    }
  }
  EXPECT_GT(reached, 100);
}

// A search space's distance tables are built on several threads: the same tables, and the same
// problem (the first robot, in order, whose target cannot be reached) as on one.
TEST(SearchSpaceDistances, SeveralThreadsBuildWhatOneBuilds) {
  const GridMap map = mapFromRows({"..........",
                                   "....@.....",
                                   "....@.....",
                                   "....@.....",
                                   "....@....."});
  // Targets across the wall for r2 and r4: reachable through the gap in the first row, and
  // not once the wall is closed.
  const std::vector<Robot> robots = {dot("r0", {0, 0, 0}, {3, 4, 1}), dot("r1", {1, 0, 0}, {2, 4, 1}),
                                     dot("r2", {2, 0, 0}, {7, 2, 1}), dot("r3", {3, 0, 0}, {0, 4, 1}),
                                     dot("r4", {0, 2, 0}, {8, 3, 1}), dot("r5", {1, 2, 0}, {3, 2, 1})};
  for (bool walled_in : {false, true}) {
    GridMap m = map;
    if (walled_in) m = mapFromRows({"....@.....", "....@.....", "....@.....", "....@.....", "....@....."});
    const World w(m, robots);
    Subproblem one = allRobots(w), two = allRobots(w);
    two.threads = 2;
    const SearchSpace a(one), b(two);
    EXPECT_EQ(a.problem(), b.problem());
    if (walled_in) {
      EXPECT_NE(a.problem().find("'r2'"), std::string::npos) << "[" << a.problem() << "]";
      continue;
    }
    ASSERT_TRUE(a.problem().empty()) << a.problem();
    for (int r = 0; r < a.numAgents(); ++r) {
      for (StateId s = 0; s < a.graph(r).stateIdCount(); ++s) ASSERT_EQ(a.distance(r, s), b.distance(r, s));
    }
  }
}

}  // namespace
}  // namespace fleet_planner::test
