// PlanFleet's subproblem report of an LA-CBS search stopped by its limit: with a budget of
// constraint-tree nodes (the same answer on every machine) raw LA-CBS on the swap of three
// robots returns the best plan it found, valid, marked `stopped_early`, with a lower bound below
// its cost; with no budget it proves its optimum and is not marked.
#include <gtest/gtest.h>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/ros/conversions.h"
#include "fleet_planner/ros/fleet_planning_service.h"
#include "ros_test_util.h"

namespace fleet_planner::test {
namespace {

using Request = fleet_planner::PlanFleet::Request;
using Response = fleet_planner::PlanFleet::Response;

Response rawLaCbs(long long max_nodes) {
  PlannerConfig config;
  config.fallback = "";  // the plan of LA-CBS, not a fallback's
  if (max_nodes >= 0) config.backend_parameters["la_cbs"]["max_high_level_nodes"] = static_cast<double>(max_nodes);
  FleetPlanningService service(config);
  service.setMap(occupancyGrid(24, 12, kRes, kOx, kOy, {{8, 8}, {8, 9}, {15, 1}}));
  service.setFootprints(registry());
  Request request = swapRequest();
  request.backend = "la_cbs";
  request.decomposition = Request::DECOMPOSITION_RAW;
  request.time_limit = 60.0;
  return service.plan(request, nullptr).response;
}

void expectValid(const Response& response) {
  ASSERT_EQ(response.status, Response::SUCCESS) << response.message;
  const GridMap map = convert(occupancyGrid(24, 12, kRes, kOx, kOy, {{8, 8}, {8, 9}, {15, 1}}), OccupancyPolicy{});
  ActionModel model;
  model.allow_backward = response.statistics.backward_moves;
  model.step = static_cast<int>(response.statistics.lattice_step);
  const auto validation = validatePlan(map, instanceOf(swapRequest(), registry(), response, kRes), planOf(response), model);
  EXPECT_TRUE(validation.valid()) << validation.violation.message;
}

TEST(StoppedEarlyService, ANodeBudgetGivesTheBestPlanFoundMarkedWithItsBound) {
  const Response cut = rawLaCbs(40);  // a plan by about 20 nodes, its optimum proven by about 320
  expectValid(cut);
  ASSERT_EQ(cut.subproblems.size(), 1u);
  EXPECT_TRUE(cut.subproblems[0].stopped_early);
  EXPECT_GE(cut.subproblems[0].lower_bound, 0);
  // One subproblem: its cost is the plan's SOC, both in time steps.
  EXPECT_LT(cut.subproblems[0].lower_bound, cut.statistics.soc);
}

TEST(StoppedEarlyService, AnOptimumProvenIsNotMarked) {
  const Response full = rawLaCbs(-1);
  expectValid(full);
  ASSERT_EQ(full.subproblems.size(), 1u);
  EXPECT_FALSE(full.subproblems[0].stopped_early);
}

}  // namespace
}  // namespace fleet_planner::test
