#pragma once
// Robots for the tests, shared by every test binary.
#include <string>
#include <vector>

#include "fleet_planner/model/instance.h"

namespace fleet_planner::test {

inline Robot makeRobot(const std::string& id, Footprint footprint, GridPose start, GridPose target) {
  Robot r;
  r.id = id;
  r.footprint = std::move(footprint);
  r.start = start;
  r.target = target;
  return r;
}

/// A one-cell robot (circle of radius 0.4).
inline Robot dot(const std::string& id, GridPose start, GridPose target) {
  return makeRobot(id, Footprint::circle(0.4), start, target);
}

inline std::vector<Footprint> footprintsOf(const Instance& instance) {
  std::vector<Footprint> fps;
  for (const Robot& r : instance.robots) fps.push_back(r.footprint);
  return fps;
}

}  // namespace fleet_planner::test
