#include "fleet_planner/ros/progress_matching.h"

#include <algorithm>
#include <cmath>

#include "fleet_planner/ros/conversions.h"

namespace fleet_planner {

ProgressMatcher::ProgressMatcher(std::vector<geometry_msgs::Pose2D> states, double position_tolerance,
                                 double heading_tolerance)
    : states_(std::move(states)), tol_(position_tolerance), yaw_tol_(heading_tolerance) {}

bool ProgressMatcher::same(int a, int b) const {
  const auto &s = states_[a], &t = states_[b];
  return s.x == t.x && s.y == t.y && s.theta == t.theta;
}

double ProgressMatcher::distance(const geometry_msgs::Pose2D& pose, const geometry_msgs::Pose2D& s) const {
  // Metres, a turn of heading_tolerance counting as much as position_tolerance.
  return std::hypot(pose.x - s.x, pose.y - s.y) + std::abs(wrapAngle(pose.theta - s.theta)) * tol_ / yaw_tol_;
}

bool ProgressMatcher::at(const geometry_msgs::Pose2D& pose, int k) const {
  const auto& s = states_[k];
  if (std::hypot(pose.x - s.x, pose.y - s.y) > tol_ || std::abs(wrapAngle(pose.theta - s.theta)) > yaw_tol_) {
    return false;
  }
  // Nearer to k than to its distinct neighbours: a short move (a lattice connection) may end
  // within the tolerance of where it began.
  const double d = distance(pose, s);
  for (int n : {k - 1, k + 1}) {
    if (n < 0 || n > lastState() || same(n, k)) continue;
    const double dn = distance(pose, states_[n]);
    if (dn < d || (dn == d && n < k)) return false;
  }
  return true;
}

bool ProgressMatcher::inside(const geometry_msgs::Pose2D& pose, int k) const {
  const auto &a = states_[k], &b = states_[k + 1];
  const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
  const double turn = wrapAngle(b.theta - a.theta), turned = wrapAngle(pose.theta - a.theta);
  if (len > 2 * tol_) {  // a move: near the segment, beyond the tolerance of both ends, on its heading
    const double along = ((pose.x - a.x) * dx + (pose.y - a.y) * dy) / len;
    const double across = std::abs((pose.x - a.x) * dy - (pose.y - a.y) * dx) / len;
    return across <= tol_ && along > tol_ && along < len - tol_ && std::abs(turned) <= yaw_tol_;
  }
  if (len > 0 || std::hypot(pose.x - a.x, pose.y - a.y) > tol_) return false;  // a short move: its ends only
  return turn >= 0 ? turned > yaw_tol_ && turned < turn - yaw_tol_ : turned < -yaw_tol_ && turned > turn + yaw_tol_;
}

int ProgressMatcher::match(const geometry_msgs::Pose2D& pose, int from, int to) const {
  for (int k = from; k <= to; ++k) {
    if (at(pose, k)) {
      while (k < to && same(k + 1, k)) ++k;  // the plan's waits there are done too
      return k;
    }
    if (k < to && inside(pose, k)) return k;
  }
  return -1;
}

double ProgressMatcher::distanceToPath(const geometry_msgs::Pose2D& pose, int from, int to) const {
  double best = std::hypot(pose.x - states_[from].x, pose.y - states_[from].y);
  for (int k = from; k < to; ++k) {
    const auto &a = states_[k], &b = states_[k + 1];
    const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
    const double f = len2 > 0 ? std::clamp(((pose.x - a.x) * dx + (pose.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(pose.x - (a.x + f * dx), pose.y - (a.y + f * dy)));
  }
  return best;
}

int ProgressMatcher::releaseCap(int from, int to, int window) const {
  const int last = std::min(to, from + window);
  int cap = from;
  for (int k = from + 1; k <= last; ++k) {
    if (same(k, k - 1)) {
      cap = k;
      continue;
    }
    // Standing at k (at the end of the waits that follow it, if released that far).
    int end = k;
    while (end < last && same(end + 1, k)) ++end;
    if (match(states_[k], from, end) != end) break;
    cap = k;
  }
  return std::max(cap, std::min(from + 1, to));
}

}  // namespace fleet_planner
