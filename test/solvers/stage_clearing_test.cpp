// Returning robots clearing the stage for a plan made without them (stage_clearing.h), and the
// pocket repair with two robots parking (pocket_repair.h): every plan passes the validator.
#include <gtest/gtest.h>

#include <algorithm>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/solvers/lns/pocket_repair.h"
#include "fleet_planner/solvers/lns/stage_clearing.h"
#include "fleet_planner/solvers/search/solve_common.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

StatePath shortestPath(const SearchSpace& space, int a) {
  const LowLevelResult r = spaceTimeAStar(space, a, AgentConstraints{}, Deadline::in(5.0));
  return r.outcome == LowLevelResult::Outcome::Found ? r.path : StatePath{};
}

// A corridor with one pocket, three cells deep, below x = 6: "a" drives east through "b"'s
// start, "b" west through "a"'s; "r" (of another subproblem) stands in the pocket's mouth.
struct MouthWorld {
  explicit MouthWorld(GridPose r_stands)
      : w(mapFromRows({"..............", "@@@@@@.@@@@@@@", "@@@@@@.@@@@@@@", "@@@@@@.@@@@@@@"}),
          {dot("a", {1, 0, 0}, {12, 0, 0}), dot("b", {10, 0, 1}, {2, 0, 1}), dot("r", {6, 3, 2}, {6, 3, 2})}),
        movers(allRobots(w)),
        all(allRobots(w)) {
    movers.robots = {0, 1};
    all.returning = {{2, r_stands}};
  }
  World w;
  Subproblem movers, all;
};

// The plan of "a" and "b" made without "r": "b" waits in the pocket's mouth.
std::vector<StatePath> planWithout(const SearchSpace& alone) {
  SoftPathTable table(alone);
  long long expansions = 0;
  const auto paths = pocketRepair(alone, table, 0, {1}, shortestPath(alone, 0), Deadline::in(5.0),
                                  PocketRepairOptions{}, expansions);
  if (!paths) return {};
  return {(*paths)[0], (*paths)[1], {}};
}

TEST(StageClearing, TheRobotInTheWayBacksIntoThePocketAndReturns) {
  const MouthWorld m({6, 1, 2});
  const SearchSpace alone(m.movers), space(m.all);
  const std::vector<StatePath> without = planWithout(alone);
  ASSERT_FALSE(without.empty());
  long long expansions = 0;
  const auto paths = clearTheStage(space, {false, false, true}, without, Deadline::in(5.0), 8, 100'000, expansions);
  ASSERT_TRUE(paths.has_value());
  EXPECT_GT(expansions, 0);
  const ValidationResult v = validateStatePaths(m.w, m.all, space, *paths);
  EXPECT_TRUE(v.valid()) << violationName(v.violation.kind);
  const Path r = toPosePaths(space, *paths)[2];
  EXPECT_EQ(r.front(), (GridPose{6, 1, 2}));
  EXPECT_EQ(r.back(), (GridPose{6, 1, 2}));
  EXPECT_TRUE(std::any_of(r.begin(), r.end(), [](const GridPose& p) { return p.y > 1; })) << "r never backed in";
  for (int a : {0, 1}) {
    ASSERT_GE((*paths)[a].size(), without[a].size());
    EXPECT_TRUE(std::equal(without[a].rbegin(), without[a].rend(), (*paths)[a].rbegin()))
        << space.label(a) << " does not end with its plan made without r";
  }
  const auto again = clearTheStage(space, {false, false, true}, without, Deadline::in(5.0), 8, 100'000, expansions);
  ASSERT_TRUE(again.has_value());
  EXPECT_EQ(*again, *paths) << "same input, same paths";
}

TEST(StageClearing, NobodyInTheWayNothingToClear) {
  const MouthWorld m({6, 3, 2});  // r stands at the pocket's bottom, off the plan
  const SearchSpace alone(m.movers), space(m.all);
  const std::vector<StatePath> without = planWithout(alone);
  ASSERT_FALSE(without.empty());
  long long expansions = 0;
  EXPECT_FALSE(clearTheStage(space, {false, false, true}, without, Deadline::in(5.0), 8, 100'000, expansions));
}

TEST(PocketRepair, TwoRobotsWaitInTwoPocketsWhileAThirdPasses) {
  // "a" drives the corridor east; "b" and "c" drive it west, through "a"'s way; pockets below
  // x = 5 and x = 9.
  const World w(mapFromRows({"..............", "@@@@@.@@@.@@@@"}),
                {dot("a", {1, 0, 0}, {13, 0, 0}), dot("b", {12, 0, 1}, {3, 0, 1}), dot("c", {10, 0, 1}, {2, 0, 1})});
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  SoftPathTable table(space);
  long long expansions = 0;
  const auto paths = pocketRepair(space, table, 0, {2, 1}, shortestPath(space, 0), Deadline::in(5.0),
                                  PocketRepairOptions{}, expansions);
  ASSERT_TRUE(paths.has_value());
  EXPECT_FALSE(table.contains(0) || table.contains(1) || table.contains(2)) << "the table is left as it was";
  const ValidationResult v = validateStatePaths(w, sub, space, {(*paths)[0], (*paths)[2], (*paths)[1]});
  EXPECT_TRUE(v.valid()) << violationName(v.violation.kind);
}

}  // namespace
}  // namespace fleet_planner::test
