#pragma once
/// When the execution runner tries an automatic re-plan of a robot again (execution_runner.h).
///
/// A refused re-plan (no way around the robot waited for, a target it covers, a search out of
/// time) gives the same answer as long as nothing it depends on has moved, and each try holds
/// the execution lock for up to replan_time_limit. So each key (a robot and a reason) is tried at
/// most once per `base_s`; each refusal doubles its wait, up to `max_s`, until the key's
/// `cause` changes (for a BLOCKED robot: the robot it waits for and its progress; for one off its
/// path: every robot's progress) or a re-plan is merged, which bring the wait back to `base_s`.
/// Times are seconds on any one clock.
#include <map>
#include <string>

namespace fleet_planner {

class ReplanBackoff {
 public:
  /// base_s > 0, max_s >= base_s.
  ReplanBackoff(double base_s, double max_s);

  /// True when `key` may be tried at `now_s`, given its `cause` now.
  bool due(const std::string& key, double now_s, const std::string& cause) const;
  /// Records a try of `key` at `now_s` with `cause`; `merged`: the re-plan is being executed.
  void record(const std::string& key, double now_s, const std::string& cause, bool merged);
  /// Seconds `key` waits after its last try (base_s when never tried).
  double wait(const std::string& key) const;
  /// Forgets every try (a new plan).
  void clear() { tries_.clear(); }

 private:
  struct Try {
    double at_s;
    double wait_s;
    std::string cause;
  };
  double base_s_, max_s_;
  std::map<std::string, Try> tries_;
};

}  // namespace fleet_planner
