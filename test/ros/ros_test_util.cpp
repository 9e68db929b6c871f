#include "ros_test_util.h"

#include "fleet_planner/ros/conversions.h"

namespace fleet_planner::test {

nav_msgs::OccupancyGrid occupancyGrid(int width, int height, double resolution, double ox, double oy,
                                      const std::vector<std::pair<int, int>>& blocked) {
  nav_msgs::OccupancyGrid grid;
  grid.header.frame_id = "map";
  grid.info.width = width;
  grid.info.height = height;
  grid.info.resolution = static_cast<float>(resolution);
  grid.info.origin.position.x = ox;
  grid.info.origin.position.y = oy;
  grid.info.origin.orientation.w = 1.0;
  grid.data.assign(static_cast<std::size_t>(width) * height, 0);
  for (int x = 0; x < width; ++x) grid.data[x] = grid.data[(height - 1) * width + x] = 100;
  for (int y = 0; y < height; ++y) grid.data[y * width] = grid.data[y * width + width - 1] = 100;
  for (const auto& [x, y] : blocked) grid.data[y * width + x] = 100;
  return grid;
}

fleet_planner::RobotFootprint circleFootprint(const std::string& id, double radius) {
  fleet_planner::RobotFootprint f;
  f.robot_id = id;
  f.type = fleet_planner::RobotFootprint::CIRCLE;
  f.radius = radius;
  return f;
}

fleet_planner::RobotFootprint blockFootprint(const std::string& id, double min_x, double max_x, double min_y,
                                             double max_y) {
  fleet_planner::RobotFootprint f;
  f.robot_id = id;
  f.type = fleet_planner::RobotFootprint::BLOCK;
  f.min_x = min_x, f.max_x = max_x, f.min_y = min_y, f.max_y = max_y;
  return f;
}

fleet_planner::RobotTask task(const std::string& id, double sx, double sy, double syaw, double gx, double gy,
                              double gyaw) {
  fleet_planner::RobotTask t;
  t.robot_id = id;
  t.start.x = sx, t.start.y = sy, t.start.theta = syaw;
  t.goal.x = gx, t.goal.y = gy, t.goal.theta = gyaw;
  return t;
}

fleet_planner::FleetFootprints registry() {
  fleet_planner::FleetFootprints fleet;
  fleet.robots = {circleFootprint("amr_1", 0.3), circleFootprint("amr_2", 0.2),
                  blockFootprint("tug", -0.4, 0.4, -0.2, 0.2)};
  return fleet;
}

fleet_planner::PlanFleet::Request swapRequest() {
  constexpr double kPi = 3.14159265358979323846;
  fleet_planner::PlanFleet::Request request;
  request.tasks = {task("amr_1", cx(3), cy(3), 0, cx(19), cy(8), 0),
                   task("amr_2", cx(19), cy(3), kPi, cx(3), cy(8), kPi),
                   task("tug", cx(11), cy(6), 0, cx(11), cy(3), kPi / 2)};
  request.time_limit = 10.0;
  return request;
}

Plan planOf(const fleet_planner::PlanFleet::Response& response) {
  Plan plan;
  for (const auto& timeline : response.timelines) {
    Path path;
    for (const auto& s : timeline.states) path.push_back({s.cell_x, s.cell_y, s.heading});
    plan.paths.push_back(path);
  }
  return plan;
}

Instance instanceOf(const fleet_planner::PlanFleet::Request& request, const fleet_planner::FleetFootprints& fleet,
                    const fleet_planner::PlanFleet::Response& response, double resolution) {
  Instance instance;
  for (std::size_t i = 0; i < request.tasks.size(); ++i) {
    Robot robot;
    robot.id = request.tasks[i].robot_id;
    for (const auto& f : fleet.robots) {
      if (f.robot_id == robot.id) robot.footprint = convert(f, resolution);
    }
    const auto& states = response.timelines.at(i).states;
    robot.start = {states.front().cell_x, states.front().cell_y, states.front().heading};
    robot.target = {states.back().cell_x, states.back().cell_y, states.back().heading};
    instance.robots.push_back(robot);
  }
  return instance;
}

}  // namespace fleet_planner::test
