// The node's allow_backward parameter: a tug facing the end of a corridor too narrow to turn in
// backs out of it, the response says backward moves were allowed, and the execution monitor
// follows the backward moves to the goal; with the parameter off the tug cannot leave.
#include <gtest/gtest.h>

#include <memory>

#include <fleet_planner/RobotExecution.h>
#include <fleet_planner/RobotResult.h>

#include "fleet_planner/ros/execution_monitor.h"
#include "fleet_planner/ros/fleet_planning_service.h"
#include "ros_test_util.h"

namespace fleet_planner::test {
namespace {

/// The hall with a corridor of rows 5..7 from column 12 to the east wall (rows 4 and 8
/// blocked there): the tug (0.8 x 0.4 m) fits in it, a quarter turn (a disc of 0.9 m) does not.
std::unique_ptr<FleetPlanningService> hallWithCorridor(bool allow_backward) {
  PlannerConfig config;
  config.allow_backward = allow_backward;
  auto service = std::make_unique<FleetPlanningService>(config);
  std::vector<std::pair<int, int>> walls;
  for (int x = 12; x < 24; ++x) walls.insert(walls.end(), {{x, 4}, {x, 8}});
  service->setMap(occupancyGrid(24, 12, kRes, kOx, kOy, walls));
  service->setFootprints(registry());
  return service;
}

/// The tug deep in the corridor facing its end; its goal in the open part, facing the same way.
fleet_planner::PlanFleet::Request tugBacksOut() {
  fleet_planner::PlanFleet::Request request;
  request.tasks = {task("tug", cx(19), cy(6), 0, cx(4), cy(6), 0)};
  request.time_limit = 10.0;
  return request;
}

TEST(BackwardMovesService, TheTugBacksOutAndTheMonitorFollowsIt) {
  const PlanCall call = hallWithCorridor(true)->plan(tugBacksOut(), nullptr);
  ASSERT_EQ(call.response.status, fleet_planner::PlanFleet::Response::SUCCESS) << call.response.message;
  EXPECT_TRUE(call.response.statistics.backward_moves);
  ASSERT_TRUE(call.executable);
  const auto& states = call.response.timelines[0].states;
  ASSERT_GE(states.size(), 2u);
  EXPECT_GT(states.front().cell_x, states.back().cell_x);  // it went west ...
  for (const auto& s : states) EXPECT_EQ(s.heading, 0);      // ... facing east all the way

  ExecutionMonitor monitor{ExecutionSettings{}};
  monitor.start(*call.executable, 0.5, "map", ros::Time(100));
  std::vector<std::optional<geometry_msgs::Pose2D>> poses = {call.executable->poses[0][0]};
  double t = 100;
  fleet_planner::FleetExecution e = monitor.update(poses, ros::Time(t));
  for (int round = 0; round < 1000 && !e.done; ++round) {
    poses[0] = monitor.plan().poses[0][e.robots[0].released];
    t += 0.5;
    e = monitor.update(poses, ros::Time(t));
  }
  EXPECT_TRUE(e.done);
  EXPECT_EQ(e.collisions, 0u);
  EXPECT_EQ(e.robots[0].state, fleet_planner::RobotExecution::ARRIVED);
}

TEST(BackwardMovesService, WithoutThemTheTugCannotLeave) {
  const PlanCall call = hallWithCorridor(false)->plan(tugBacksOut(), nullptr);
  EXPECT_NE(call.response.status, fleet_planner::PlanFleet::Response::SUCCESS);
  EXPECT_EQ(call.response.robots[0].status, fleet_planner::RobotResult::UNREACHABLE) << call.response.message;
}

}  // namespace
}  // namespace fleet_planner::test
