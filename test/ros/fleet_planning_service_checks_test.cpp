// The PlanFleet service's checks that need no plan: the request checks the node answers at
// once (even while another call plans) and the status names of the messages.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "fleet_planner/ros/conversions.h"
#include "fleet_planner/ros/fleet_planning_service.h"
#include "ros_test_util.h"

namespace fleet_planner::test {
namespace {

using Request = fleet_planner::PlanFleet::Request;
using Response = fleet_planner::PlanFleet::Response;
using RobotResultMsg = fleet_planner::RobotResult;

TEST(PlanningServiceChecks, BadRequestsAreAnsweredWithoutMapOrRegistry) {
  // checkRequest() is what the node answers at once, even while another call plans.
  const FleetPlanningService service{PlannerConfig{}};
  Request request = swapRequest();
  EXPECT_FALSE(service.checkRequest(request).has_value());
  EXPECT_DOUBLE_EQ(service.timeLimit(request), 10.0);
  request.time_limit = -1;
  EXPECT_DOUBLE_EQ(service.timeLimit(request), PlannerConfig{}.time_limit);

  const std::vector<std::pair<std::function<void(Request&)>, std::string>> cases = {
      {[](Request& r) { r.tasks.clear(); }, "tasks is empty"},
      {[](Request& r) { r.tasks[1].robot_id = ""; }, "tasks[1]: robot_id is empty"},
      {[](Request& r) { r.tasks[2].robot_id = "amr_1"; }, "robot 'amr_1' has two tasks (tasks[0] and tasks[2])"},
      {[](Request& r) { r.time_limit = 1e12; }, "max_time_limit"},
      {[](Request& r) { r.backend = "teleport"; }, "no backend named 'teleport'"},
      {[](Request& r) { r.tasks[0].goal.x = NAN; }, "robot 'amr_1': goal x is nan"},
  };
  for (const auto& [spoil, words] : cases) {
    request = swapRequest();
    spoil(request);
    const auto answer = service.checkRequest(request);
    ASSERT_TRUE(answer.has_value()) << words;
    EXPECT_NE(answer->status, Response::SUCCESS);
    EXPECT_NE(answer->message.find(words), std::string::npos) << answer->message;
  }
  // A start from TF is not checked: its pose fields are ignored.
  request = swapRequest();
  request.tasks[0].start_from_tf = true;
  request.tasks[0].start.x = NAN;
  EXPECT_FALSE(service.checkRequest(request).has_value());
}

TEST(StatusNames, NameEveryConstant) {
  EXPECT_EQ(fleetStatusName(Response::SUCCESS), "SUCCESS");
  EXPECT_EQ(fleetStatusName(Response::BUSY), "BUSY");
  EXPECT_EQ(fleetStatusName(Response::INTERNAL_ERROR), "INTERNAL_ERROR");
  EXPECT_EQ(fleetStatusName(200), "STATUS_200");
  EXPECT_EQ(robotStatusName(RobotResultMsg::INVALID_FOOTPRINT), "INVALID_FOOTPRINT");
  EXPECT_EQ(robotStatusName(RobotResultMsg::NOT_PLANNED), "NOT_PLANNED");
}

}  // namespace
}  // namespace fleet_planner::test
