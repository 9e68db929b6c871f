// Two agents trading places through a pocket (pocket_repair.h): in a corridor with one side
// pocket, where the ordered repair fails in both orders, the parking agent waits in the pocket
// and both paths pass the plan validator; without the pocket there is no repair.
#include <gtest/gtest.h>

#include <algorithm>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/solvers/lns/ordered_repair.h"
#include "fleet_planner/solvers/lns/pocket_repair.h"
#include "fleet_planner/solvers/search/solve_common.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

// "t" stands at the corridor's west end for good (in the table); "a" drives the corridor east
// through "b"'s start, "b" drives it west through "a"'s start.
World swapWorld(bool pocket) {
  return World(mapFromRows({"..............", pocket ? "@@@@@@.@@@@@@@" : "@@@@@@@@@@@@@@",
                            pocket ? "@@@@@@.@@@@@@@" : "@@@@@@@@@@@@@@"}),
               {dot("t", {0, 0, 0}, {0, 0, 0}), dot("a", {1, 0, 0}, {12, 0, 0}),
                dot("b", {10, 0, 2}, {2, 0, 2})});
}

StatePath shortestPath(const SearchSpace& space, int a) {
  const LowLevelResult r = spaceTimeAStar(space, a, AgentConstraints{}, Deadline::in(5.0));
  return r.outcome == LowLevelResult::Outcome::Found ? r.path : StatePath{};
}

TEST(PocketRepair, TheParkingAgentWaitsInThePocketAndNobodyCollides) {
  const World w = swapWorld(/*pocket=*/true);
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  SoftPathTable table(space);
  const StatePath runner = shortestPath(space, 0);
  ASSERT_FALSE(runner.empty());
  table.insert(0, runner);
  long long expansions = 0;
  for (const std::vector<int>& order : {std::vector<int>{1, 2}, std::vector<int>{2, 1}}) {
    EXPECT_FALSE(orderedRepair(space, table, order, Deadline::in(5.0), 100'000, expansions))
        << "each start is on the other's way: no order works";
  }
  for (const auto& [through, parks] : {std::pair{1, 2}, std::pair{2, 1}}) {
    expansions = 0;
    const auto paths = pocketRepair(space, table, through, {parks}, shortestPath(space, through),
                                    Deadline::in(5.0), PocketRepairOptions{}, expansions);
    ASSERT_TRUE(paths.has_value()) << space.label(parks) << " parking";
    EXPECT_GT(expansions, 0);
    EXPECT_FALSE(table.contains(1) || table.contains(2)) << "the table is left as it was";
    ASSERT_TRUE(table.contains(0));
    std::vector<StatePath> all{runner, {}, {}};
    all[through] = (*paths)[0];
    all[parks] = (*paths)[1];
    Plan plan;
    plan.paths = toPosePaths(space, all);
    const ValidationResult v = validatePlan(w.map, w.instance, plan);
    EXPECT_TRUE(v.valid()) << violationName(v.violation.kind) << " with " << space.label(parks)
                           << " parking";
    const Path& parked = plan.paths[parks];
    EXPECT_TRUE(std::any_of(parked.begin(), parked.end(), [](const GridPose& p) { return p.y > 0; }))
        << space.label(parks) << " never enters the pocket";
    const auto again = pocketRepair(space, table, through, {parks}, shortestPath(space, through),
                                    Deadline::in(5.0), PocketRepairOptions{}, expansions);
    ASSERT_TRUE(again.has_value());
    EXPECT_EQ(*again, *paths) << "same input, same paths";
  }
}

TEST(PocketRepair, NoPocketNoRepair) {
  const World w = swapWorld(/*pocket=*/false);
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  SoftPathTable table(space);
  long long expansions = 0;
  for (const auto& [through, parks] : {std::pair{1, 2}, std::pair{2, 1}}) {
    EXPECT_FALSE(pocketRepair(space, table, through, {parks}, shortestPath(space, through),
                              Deadline::in(5.0), PocketRepairOptions{}, expansions));
  }
  EXPECT_FALSE(table.contains(1) || table.contains(2));
}

}  // namespace
}  // namespace fleet_planner::test
