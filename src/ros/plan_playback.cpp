#include "fleet_planner/ros/plan_playback.h"

#include <algorithm>

#include "fleet_planner/ros/conversions.h"

namespace fleet_planner {

geometry_msgs::Pose2D poseAt(const fleet_planner::RobotTimeline& timeline, double seconds) {
  const auto& states = timeline.states;
  geometry_msgs::Pose2D pose;
  // The first state whose time is after `seconds`.
  const auto next = std::upper_bound(states.begin(), states.end(), seconds,
                                     [](double t, const fleet_planner::TimedState& s) { return t < s.time; });
  if (next == states.begin() || next == states.end()) {
    const auto& s = next == states.begin() ? states.front() : states.back();
    pose.x = s.x, pose.y = s.y, pose.theta = s.yaw;
    return pose;
  }
  const auto& b = *next;
  const auto& a = *(next - 1);
  const double span = b.time - a.time;
  const double f = span > 0 ? (seconds - a.time) / span : 1.0;
  pose.x = a.x + f * (b.x - a.x);
  pose.y = a.y + f * (b.y - a.y);
  pose.theta = wrapAngle(a.yaw + f * wrapAngle(b.yaw - a.yaw));
  return pose;
}

double planDuration(const std::vector<fleet_planner::RobotTimeline>& timelines) {
  double end = 0.0;
  for (const auto& t : timelines) {
    if (!t.states.empty()) end = std::max(end, t.states.back().time);
  }
  return end;
}

}  // namespace fleet_planner
