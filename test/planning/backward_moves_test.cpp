// Backward moves (ActionModel::allow_backward) through the facade: robots facing the end of a
// corridor too narrow to turn in back out; without backward moves they cannot leave, and the
// validator rejects a plan with backward moves unless they are allowed.
#include <gtest/gtest.h>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/planning/plan_fleet.h"
#include "test_maps.h"
#include "test_robots.h"

namespace fleet_planner::test {
namespace {

/// A 30 x 20 room with a dead-end corridor of 6 rows (y 7..12) running from x = 30 to x = 59.
GridMap roomWithCorridor() {
  std::vector<std::string> rows(20, std::string(60, '.'));
  for (int y = 0; y < 20; ++y) {
    for (int x = 30; x < 60; ++x) {
      if (y < 7 || y > 12) rows[y][x] = '@';
    }
  }
  return mapFromRows(rows);
}

/// Robots 6 cells long and 4 wide: a quarter turn sweeps a disc of radius 3.6, wider than the
/// corridor. Both stand in it facing its end (heading 0 is +x), the deeper one first.
Instance twoFacingTheEnd() {
  Instance instance;
  const Footprint body = Footprint::block(-3, -2, 3, 2);
  instance.robots = {makeRobot("deep", body, {52, 10, 0}, {6, 4, 0}),
                     makeRobot("near", body, {42, 10, 0}, {6, 15, 0})};
  return instance;
}

PlanningOptions options(bool backward, int step) {
  PlanningOptions o;
  o.model.allow_backward = backward;
  o.lattice_step = step;
  o.threads = 1;
  o.time_limit = 20.0;
  return o;
}

int backwardMoves(const Plan& plan, const ActionModel& model) {
  int count = 0;
  for (const Path& p : plan.paths) {
    for (std::size_t t = 0; t + 1 < p.size(); ++t) count += actionBetween(p[t], p[t + 1], model) == Action::Backward;
  }
  return count;
}

TEST(BackwardMoves, RobotsFacingTheEndOfANarrowCorridorBackOut) {
  const GridMap map = roomWithCorridor();
  const Instance instance = twoFacingTheEnd();
  for (int step : {1, 2}) {
    const PlanningResult r = planFleet(map, instance, options(true, step));
    ASSERT_TRUE(r.success()) << "step " << step << ": " << statusName(r.status) << ": " << r.reason;
    ActionModel model;
    model.allow_backward = true;
    model.step = r.lattice_step;
    const ValidationResult valid = validatePlan(map, instance, r.plan, model);
    EXPECT_TRUE(valid.valid()) << "step " << step << ": " << valid.violation.message;
    EXPECT_GE(backwardMoves(r.plan, model), 2) << "step " << step;
    // Forward moves only, the same plan is not a plan.
    model.allow_backward = false;
    EXPECT_FALSE(validatePlan(map, instance, r.plan, model).valid()) << "step " << step;
  }
}

TEST(BackwardMoves, WithoutThemTheRobotsInTheCorridorCannotLeave) {
  const PlanningResult r = planFleet(roomWithCorridor(), twoFacingTheEnd(), options(false, 1));
  EXPECT_EQ(r.status, SolveStatus::Infeasible) << r.reason;
  EXPECT_NE(r.reason.find("'deep'"), std::string::npos) << r.reason;
}

TEST(BackwardMoves, SameInputSamePlan) {
  const PlanningResult a = planFleet(roomWithCorridor(), twoFacingTheEnd(), options(true, 2));
  const PlanningResult b = planFleet(roomWithCorridor(), twoFacingTheEnd(), options(true, 2));
  ASSERT_TRUE(a.success()) << a.reason;
  EXPECT_EQ(a.plan.paths, b.plan.paths);
}

}  // namespace
}  // namespace fleet_planner::test
