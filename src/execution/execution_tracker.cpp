// The state of a plan's execution; see execution_tracker.h.
#include "fleet_planner/execution/execution_tracker.h"

#include <algorithm>
#include <string>
#include <utility>

#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

ExecutionTracker::ExecutionTracker(const Plan& plan, StepDependencies dependencies)
    : deps_(std::move(dependencies)) {
  const std::size_t n = plan.paths.size();
  if (deps_.before.size() != n) {
    throw InvalidInput("dependencies for " + std::to_string(deps_.before.size()) + " robots, plan has " +
                       std::to_string(n));
  }
  for (std::size_t i = 0; i < n; ++i) {
    const int last = static_cast<int>(plan.paths[i].size()) - 1;
    if (last < 0) throw InvalidInput("robot " + std::to_string(i) + ": path is empty");
    if (static_cast<int>(deps_.before[i].size()) != last) {
      throw InvalidInput("robot " + std::to_string(i) + ": dependencies for " +
                         std::to_string(deps_.before[i].size()) + " steps, path has " + std::to_string(last));
    }
    last_.push_back(last);
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t t = 0; t < deps_.before[i].size(); ++t) {
      for (const Requirement& r : deps_.before[i][t]) {
        if (r.robot < 0 || r.robot >= static_cast<int>(n) || r.state < 0 || r.state > last_[r.robot]) {
          throw InvalidInput("robot " + std::to_string(i) + " step " + std::to_string(t) +
                             ": requirement on robot " + std::to_string(r.robot) + " state " +
                             std::to_string(r.state) + " names no state of the plan");
        }
      }
    }
  }
  progress_.assign(n, 0);
  released_.assign(n, 0);
  finished_ = static_cast<int>(std::count(last_.begin(), last_.end(), 0));
}

ExecutionTracker::ExecutionTracker(const Plan& plan, StepDependencies dependencies, const std::vector<int>& progress)
    : ExecutionTracker(plan, std::move(dependencies)) {
  if (progress.size() != last_.size()) {
    throw InvalidInput("progress for " + std::to_string(progress.size()) + " robots, plan has " +
                       std::to_string(last_.size()));
  }
  for (int i = 0; i < robots(); ++i) reportProgress(i, progress[i]);
}

void ExecutionTracker::checkRobot(int robot) const {
  if (robot < 0 || robot >= robots()) throw InvalidInput("no robot " + std::to_string(robot) + " in the plan");
}

ExecutionTracker::Report ExecutionTracker::reportProgress(int robot, int state) {
  checkRobot(robot);
  if (state < 0 || state > last_[robot]) {
    throw InvalidInput("robot " + std::to_string(robot) + ": state " + std::to_string(state) +
                       " is not on its path (0.." + std::to_string(last_[robot]) + ")");
  }
  if (state <= progress_[robot]) return Report::Ignored;
  const bool overran = state > releasedUpTo(robot);
  progress_[robot] = state;
  if (state == last_[robot]) ++finished_;
  return overran ? Report::Overran : Report::Advanced;
}

int ExecutionTracker::releasedUpTo(int robot) const {
  checkRobot(robot);
  int& k = released_[robot];
  k = std::max(k, progress_[robot]);
  const auto& steps = deps_.before[robot];
  auto released = [&](int t) {
    return std::all_of(steps[t].begin(), steps[t].end(), [&](const Requirement& r) { return met(r); });
  };
  while (k < last_[robot] && released(k)) ++k;
  return k;
}

std::optional<Requirement> ExecutionTracker::blockedBy(int robot) const {
  const int k = releasedUpTo(robot);
  if (k == last_[robot]) return std::nullopt;
  for (const Requirement& r : deps_.before[robot][k]) {
    if (!met(r)) return r;
  }
  return std::nullopt;  // not reached: releasedUpTo stops at a step with an unmet requirement
}

}  // namespace fleet_planner
