// The node's resource limits (parameters max_map_cells, max_robots, max_memory_mb): a request
// over a limit answers RESOURCE_LIMIT with a message naming the parameter, before anything big is
// allocated, and the service goes on planning requests within the limits.
#include <gtest/gtest.h>

#include "fleet_planner/runtime/resource_limits.h"
#include "fleet_planner/ros/fleet_planning_service.h"
#include "ros_test_util.h"

namespace fleet_planner::test {
namespace {

using Request = fleet_planner::PlanFleet::Request;
using Response = fleet_planner::PlanFleet::Response;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(PlanningServiceLimits, MoreRobotsThanMaxRobotsAnswerResourceLimit) {
  PlannerConfig config;
  config.max_robots = 2;
  FleetPlanningService service(config);
  service.setMap(occupancyGrid(24, 12, kRes, kOx, kOy));
  service.setFootprints(registry());
  const Response r = service.plan(swapRequest(), nullptr).response;
  EXPECT_EQ(r.status, Response::RESOURCE_LIMIT);
  EXPECT_TRUE(contains(r.message, "3 robots")) << r.message;
  EXPECT_TRUE(contains(r.message, "max_robots=2")) << r.message;
  EXPECT_TRUE(r.timelines.empty());
  Request two = swapRequest();
  two.tasks.pop_back();
  EXPECT_EQ(service.plan(two, nullptr).response.status, Response::SUCCESS);
}

TEST(PlanningServiceLimits, AMapOverMaxMapCellsIsRefusedBeforeConversion) {
  PlannerConfig config;
  config.max_map_cells = 24 * 12 - 1;
  FleetPlanningService service(config);
  service.setFootprints(registry());
  EXPECT_THROW(service.setMap(occupancyGrid(24, 12, kRes, kOx, kOy)), ResourceLimitError);
  EXPECT_FALSE(service.hasMap());
  const Response r = service.plan(swapRequest(), nullptr).response;
  EXPECT_EQ(r.status, Response::RESOURCE_LIMIT);
  EXPECT_TRUE(contains(r.message, "24 x 12 = 288 cells")) << r.message;
  EXPECT_TRUE(contains(r.message, "max_map_cells=287")) << r.message;
}

TEST(PlanningServiceLimits, ARefusedMapKeepsThePreviousOne) {
  PlannerConfig config;
  config.max_map_cells = 24 * 12;
  FleetPlanningService service(config);
  service.setFootprints(registry());
  service.setMap(occupancyGrid(24, 12, kRes, kOx, kOy));
  EXPECT_THROW(service.setMap(occupancyGrid(25, 12, kRes, kOx, kOy)), ResourceLimitError);
  EXPECT_EQ(service.plan(swapRequest(), nullptr).response.status, Response::SUCCESS);
}

TEST(PlanningServiceLimits, GraphsOverMaxMemoryAnswerResourceLimit) {
  // A limit below what the process already uses: the state graphs are refused before they are
  // built, with the estimate and the robots in the message.
  PlannerConfig config;
  config.max_memory_mb = 1;
  FleetPlanningService service(config);
  service.setMap(occupancyGrid(24, 12, kRes, kOx, kOy));
  service.setFootprints(registry());
  const Response r = service.plan(swapRequest(), nullptr).response;
  EXPECT_EQ(r.status, Response::RESOURCE_LIMIT);
  EXPECT_TRUE(contains(r.message, "max_memory_mb=1")) << r.message;
  EXPECT_TRUE(contains(r.message, "state graphs of 3 robots")) << r.message;
  EXPECT_TRUE(contains(r.message, "estimated")) << r.message;
}

TEST(PlanningServiceLimits, GraphsBuiltPastTheDeadlineAnswerTimeout) {
  // The call's time limit includes the state graphs: a limit that passes while they are built
  // is a TIMEOUT (they used to be built in full before the deadline was even set).
  FleetPlanningService service{PlannerConfig{}};
  service.setMap(occupancyGrid(24, 12, kRes, kOx, kOy));
  service.setFootprints(registry());
  Request request = swapRequest();
  request.time_limit = 1e-9;
  const Response r = service.plan(request, nullptr).response;
  EXPECT_EQ(r.status, Response::TIMEOUT) << r.message;
  EXPECT_TRUE(contains(r.message, "state graphs")) << r.message;
  for (const auto& robot : r.robots)
    EXPECT_EQ(robot.status, fleet_planner::RobotResult::NOT_PLANNED) << robot.message;
  EXPECT_EQ(service.plan(swapRequest(), nullptr).response.status,
            Response::SUCCESS);  // nothing half-built is kept
}

TEST(PlanningServiceLimits, StatusNameOfResourceLimit) {
  EXPECT_EQ(fleetStatusName(Response::RESOURCE_LIMIT), "RESOURCE_LIMIT");
}

}  // namespace
}  // namespace fleet_planner::test
