// The test-only exhaustive reference search against hand-computed optimal SOCs. Every plan it
// returns is also checked by the plan validator and must have the SOC it claims.
#include "exhaustive_search.h"

#include <gtest/gtest.h>

#include "fleet_planner/model/plan_validator.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

/// Runs the search and checks that a returned plan is valid and has the returned SOC.
ExhaustiveResult searchChecked(const GridMap& map, const std::vector<Robot>& robots,
                               long long budget = 2000000) {
  const Instance instance = makeInstance(robots);
  ExhaustiveResult r = exhaustiveSearch(map, instance, budget);
  if (r.soc >= 0) {
    const auto v = validatePlan(map, instance, r.plan);
    EXPECT_TRUE(v.valid()) << v.violation.message;
    std::vector<GridPose> targets;
    for (const Robot& robot : robots) targets.push_back(robot.target);
    EXPECT_EQ(planMetrics(r.plan, targets).soc, r.soc);
  }
  return r;
}

TEST(ExhaustiveSearch, OneRobotThreeCellsStraight) {
  EXPECT_EQ(searchChecked(freeMap(4, 1), {dot("a", {0, 0, 0}, {3, 0, 0})}).soc, 3);
}

TEST(ExhaustiveSearch, RotationsCostOneStepEachAndThereIsNoHalfTurn) {
  EXPECT_EQ(searchChecked(freeMap(1, 1), {dot("a", {0, 0, 0}, {0, 0, 2})}).soc, 1);
  EXPECT_EQ(searchChecked(freeMap(1, 1), {dot("a", {0, 0, 0}, {0, 0, 1})}).soc, 2);
}

TEST(ExhaustiveSearch, RobotsAlreadyAtTargetsCostNothing) {
  EXPECT_EQ(
      searchChecked(freeMap(3, 2), {dot("a", {0, 0, 0}, {0, 0, 0}), bar("b", {1, 1, 0}, {1, 1, 0})})
          .soc,
      0);
}

TEST(ExhaustiveSearch, IndependentRobotsAddUp) {
  // Three robots on their own rows: 3 + 3 + (3 + one rotation) = 10.
  const auto r =
      searchChecked(freeMap(4, 3), {dot("a", {0, 0, 0}, {3, 0, 0}), dot("b", {3, 1, 1}, {0, 1, 1}),
                                    dot("c", {0, 2, 0}, {3, 2, 2})});
  EXPECT_EQ(r.soc, 10);
}

TEST(ExhaustiveSearch, SwapInAOneWideCorridorIsImpossible) {
  const auto r = searchChecked(freeMap(4, 1),
                               {dot("a", {0, 0, 0}, {3, 0, 0}), dot("b", {3, 0, 1}, {0, 0, 1})});
  EXPECT_EQ(r.soc, -1);
  EXPECT_FALSE(r.budget_exhausted);
}

TEST(ExhaustiveSearch, RobotWaitsUntilTheOtherHasLeftTheJunction) {
  // b drops from (2, 1) onto its target (2, 0) in a's lane. Going first would block a for good,
  // so b waits until a has left (2, 0) and entered (3, 0) (t = 3), then moves at step 3 -> 4:
  // a = 4, b = 4 (alone b would need 1).
  const auto r = searchChecked(freeMap(5, 2),
                               {dot("a", {0, 0, 0}, {4, 0, 0}), dot("b", {2, 1, 3}, {2, 0, 3})});
  EXPECT_EQ(r.soc, 8);
}

TEST(ExhaustiveSearch, RobotOnItsTargetStepsAsideAndReturns) {
  // a sits on its target (1, 0) facing +y; b must drive through (1, 0). a escapes into the pocket
  // (1, 1) (t = 1), turns round (t = 3), comes back (t = 4) and turns to +y again (t = 6); b
  // enters (1, 0) in step 1 -> 2 and reaches (2, 0) at t = 3. SOC = 6 + 3: a's cost is its
  // last arrival, not its first.
  const GridMap map = mapFromRows({"...", "@.@"});
  const auto r =
      searchChecked(map, {dot("a", {1, 0, 2}, {1, 0, 2}), dot("b", {0, 0, 0}, {2, 0, 0})});
  EXPECT_EQ(r.soc, 9);
}

TEST(ExhaustiveSearch, BlockRotationSweepIsChecked) {
  // From (1, 2) facing +x the block's turns both sweep (3, 2); with that cell blocked and no
  // backward move, the block cannot turn at all. On the free map one turn suffices.
  const Robot b = bar("b", {1, 2, 0}, {1, 2, 2});
  EXPECT_EQ(searchChecked(freeMap(5, 5), {b}).soc, 1);
  const auto r = searchChecked(mapFromRows({".....", ".....", "...@.", ".....", "....."}), {b});
  EXPECT_EQ(r.soc, -1);
  EXPECT_FALSE(r.budget_exhausted);
}

TEST(ExhaustiveSearch, TurningIntoAWaitingRobotIsNotAllowed) {
  // Both turns of the block at (1, 2) facing +x sweep (3, 2), where c sits on its target, and the
  // block has no other move. Cheapest: c drives to (4, 2) (t = 1), the block turns in step
  // 1 -> 2 (b = 2), c turns round (t = 3), comes back (t = 4) and turns to +x (t = 6): 2 + 6.
  const auto r = searchChecked(freeMap(5, 5),
                               {bar("b", {1, 2, 0}, {1, 2, 2}), dot("c", {3, 2, 0}, {3, 2, 0})});
  EXPECT_EQ(r.soc, 8);
}

TEST(ExhaustiveSearch, StopsAtTheStateBudget) {
  const auto r = searchChecked(
      freeMap(5, 4), {dot("a", {0, 0, 0}, {4, 3, 2}), dot("b", {4, 3, 1}, {0, 0, 3})}, 50);
  EXPECT_EQ(r.soc, -1);
  EXPECT_TRUE(r.budget_exhausted);
}

TEST(ExhaustiveSearch, OverlappingStartsHaveNoPlan) {
  EXPECT_EQ(
      searchChecked(freeMap(3, 1), {dot("a", {0, 0, 0}, {0, 0, 0}), bar("b", {1, 0, 1}, {1, 0, 1})})
          .soc,
      -1);
}

}  // namespace
}  // namespace fleet_planner::test
