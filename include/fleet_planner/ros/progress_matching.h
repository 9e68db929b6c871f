#pragma once
/// Which state of its plan a robot has reached, from its pose alone (TF): the execution's
/// progress. A robot stands at state k when its pose is within the tolerances of that state's
/// pose and nearer to it than to the states before and after; it is on its way from k to k + 1
/// when it is near the segment (or turn) between them, beyond the tolerance of both ends.
///
/// A path may come back to a pose (a turn and the turn back, a step aside and back), so a pose
/// can match several states. Two rules keep the progress exact:
/// - the smallest match from the known progress on is taken: it is never beyond the robot's
///   true state (which matches too), so the progress is never ahead of the robot;
/// - the robot is released no further than releaseCap(): up to the last state whose pose is
///   matched by no earlier state of the window, so a robot that stops at its release is
///   recognised there, and never taken for an earlier state (which would hold it, and those
///   waiting for it, forever).
#include <vector>

#include <geometry_msgs/Pose2D.h>

namespace fleet_planner {

class ProgressMatcher {
 public:
  /// `states`: the plan's poses of one robot, in order (non-empty).
  ProgressMatcher(std::vector<geometry_msgs::Pose2D> states, double position_tolerance, double heading_tolerance);

  /// The smallest state k in [from, to] the pose matches (stands at k, or on its way from k to
  /// k + 1 with k < to), moved on over the plan's waits there (identical poses) up to `to`; -1
  /// if none matches.
  int match(const geometry_msgs::Pose2D& pose, int from, int to) const;
  /// The largest k in [from, to], at most `window` states beyond `from`, such that a robot
  /// standing at any state of (from, k] is matched to that state (or the end of its waits);
  /// at least from + 1 when to > from.
  int releaseCap(int from, int to, int window = 64) const;

  /// Metres from `pose` to the path through states from..to (straight between states).
  double distanceToPath(const geometry_msgs::Pose2D& pose, int from, int to) const;

  int lastState() const { return static_cast<int>(states_.size()) - 1; }
  const geometry_msgs::Pose2D& state(int k) const { return states_[k]; }

 private:
  bool at(const geometry_msgs::Pose2D& pose, int k) const;
  bool inside(const geometry_msgs::Pose2D& pose, int k) const;  ///< on the way from k to k + 1
  double distance(const geometry_msgs::Pose2D& pose, const geometry_msgs::Pose2D& s) const;
  bool same(int a, int b) const;

  std::vector<geometry_msgs::Pose2D> states_;
  double tol_, yaw_tol_;
};

}  // namespace fleet_planner
