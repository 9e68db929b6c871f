#pragma once
/// The state of a plan's execution: each robot's progress (the last state of its path it has
/// reached) and, from the step dependencies (step_dependencies.h), how far each robot may drive
/// now. A plain state machine for the executing node: no clock, no ROS; the caller reports
/// progress as robots arrive and asks what is released.
///
/// Released states only grow: a requirement is on another robot's progress, which never goes
/// back, so what was released once stays released.
#include <optional>
#include <vector>

#include "fleet_planner/execution/step_dependencies.h"
#include "fleet_planner/model/plan.h"

namespace fleet_planner {

class ExecutionTracker {
 public:
  enum class Report {
    Advanced,  ///< progress moved forward
    Ignored,   ///< not beyond the progress already known (a late or repeated report)
    Overran,   ///< recorded, but beyond what was released: the guarantees no longer hold
  };

  /// Every robot at state 0. Throws InvalidInput when `dependencies` do not have one list per
  /// step of every path of `plan`, or name a robot or state that does not exist.
  ExecutionTracker(const Plan& plan, StepDependencies dependencies);
  /// Resumes an execution: each robot at `progress` (one state per robot, on its path), as after
  /// a re-plan (replanning.h) that kept the states robots have reached. Throws InvalidInput as
  /// above, and for a progress that is not a state of its robot's path.
  ExecutionTracker(const Plan& plan, StepDependencies dependencies, const std::vector<int>& progress);

  int robots() const { return static_cast<int>(last_.size()); }
  /// The robot's last state: path size - 1.
  int lastState(int robot) const { return last_.at(robot); }
  int progress(int robot) const { return progress_.at(robot); }

  /// The robot has reached `state` (0 .. lastState). Progress never goes back: an earlier state
  /// than known is ignored. Throws InvalidInput for an unknown robot or a state off its path.
  Report reportProgress(int robot, int state);

  /// The largest state k the robot may drive to now, through every state up to k: every
  /// requirement of each of its steps from its progress up to k is met (waits need none). At
  /// least its progress; its last state once nothing holds it any more.
  int releasedUpTo(int robot) const;
  /// What holds the robot at releasedUpTo (the first requirement of that step that is not met),
  /// or nothing when it is released to its last state.
  std::optional<Requirement> blockedBy(int robot) const;

  /// The robot has reached its last state.
  bool done(int robot) const { return progress_.at(robot) == last_.at(robot); }
  /// Every robot has reached its last state.
  bool done() const { return finished_ == robots(); }

  const StepDependencies& dependencies() const { return deps_; }

 private:
  bool met(const Requirement& r) const { return progress_[r.robot] >= r.state; }
  void checkRobot(int robot) const;

  StepDependencies deps_;
  std::vector<int> last_;
  std::vector<int> progress_;
  mutable std::vector<int> released_;  ///< a cache: released only grows
  int finished_ = 0;
};

}  // namespace fleet_planner
