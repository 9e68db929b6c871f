#pragma once
/// Messages for the ROS-layer tests: small occupancy grids, registry footprints, tasks, and the
/// timelines of a response turned back into a core plan for the validator.
#include <string>
#include <vector>

#include <fleet_planner/FleetFootprints.h>
#include <fleet_planner/PlanFleet.h>
#include <nav_msgs/OccupancyGrid.h>

#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"

namespace fleet_planner::test {

/// A width x height grid of `resolution` m at (ox, oy), free except a border wall and the cells
/// listed as "x,y" pairs.
nav_msgs::OccupancyGrid occupancyGrid(int width, int height, double resolution, double ox, double oy,
                                      const std::vector<std::pair<int, int>>& blocked = {});

fleet_planner::RobotFootprint circleFootprint(const std::string& id, double radius);
fleet_planner::RobotFootprint blockFootprint(const std::string& id, double min_x, double max_x, double min_y,
                                             double max_y);

fleet_planner::RobotTask task(const std::string& id, double sx, double sy, double syaw, double gx, double gy,
                              double gyaw);

/// The hall most service tests plan in: 24 x 12 cells of kRes m with the origin at (kOx, kOy).
constexpr double kRes = 0.25, kOx = -1.0, kOy = 2.0;
/// Centre of the hall's cell column i / row j, metres.
inline double cx(int i) { return kOx + (i + 0.5) * kRes; }
inline double cy(int j) { return kOy + (j + 0.5) * kRes; }
/// The hall's fleet: amr_1 and amr_2 (circles, 0.3 and 0.2 m) and tug (a 0.8 x 0.4 m block).
fleet_planner::FleetFootprints registry();
/// amr_1 and amr_2 swap sides of the hall while the tug turns from +x to +y; 10 s limit.
fleet_planner::PlanFleet::Request swapRequest();

/// The response's timelines as a core plan (grid states), in task order.
Plan planOf(const fleet_planner::PlanFleet::Response& response);

/// The request as a core instance on a map of `resolution` metres: footprints from `fleet`, start
/// and goal from the first and last timeline states (which the test checks against the request).
Instance instanceOf(const fleet_planner::PlanFleet::Request& request, const fleet_planner::FleetFootprints& fleet,
                    const fleet_planner::PlanFleet::Response& response, double resolution);

}  // namespace fleet_planner::test
