// The low-level search under area constraints that cut the target off from some time on: it
// must tell "no path" (or find the one before the cut) without filling space-time.
#include "fleet_planner/solvers/space_time_astar.h"

#include <gtest/gtest.h>

#include "fleet_planner/solvers/search_space.h"
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

}  // namespace
}  // namespace fleet_planner::test
