// A plan driven as early as its step dependencies allow; see earliest_schedule.h.
#include "fleet_planner/execution/earliest_schedule.h"

#include <algorithm>

namespace fleet_planner {

std::optional<std::vector<Path>> earliestSchedule(const PlanCells& cells, const StepDependencies& deps) {
  const int n = cells.robots();
  if (cells.from() != 0 || static_cast<int>(deps.before.size()) != n) return std::nullopt;
  int horizon = 0;
  std::vector<std::vector<int>> start(n);  // [i][t]: when move t starts (-1: a wait)
  for (int i = 0; i < n; ++i) {
    start[i].assign(cells.lastState(i), -1);
    horizon = std::max(horizon, cells.lastState(i));
  }
  std::vector<int> reached(n, 0);  // when each robot reached the state of its next step
  for (int t = 0; t < horizon; ++t) {
    for (int i = 0; i < n; ++i) {
      if (t >= cells.lastState(i) || !cells.isMove(i, t)) continue;
      int s = reached[i];
      for (const Requirement& r : deps.before[i][t]) {
        if (r.state <= 0) continue;
        const int leave = r.state - 1;  // the move that reaches the required state
        if (leave >= t || leave >= cells.lastState(r.robot) || !cells.isMove(r.robot, leave)) return std::nullopt;
        s = std::max(s, start[r.robot][leave] + 1);
      }
      start[i][t] = s;
      reached[i] = s + 1;
    }
  }
  std::vector<Path> paths(n);
  for (int i = 0; i < n; ++i) {
    const Path& given = cells.path(i);
    Path& p = paths[i];
    p.push_back(given.front());
    for (int t = 0; t < cells.lastState(i); ++t) {
      if (start[i][t] < 0) continue;
      while (static_cast<int>(p.size()) <= start[i][t]) p.push_back(p.back());
      p.push_back(given[t + 1]);
    }
  }
  return paths;
}

namespace {

// Trailing waits mean nothing (a robot parks at its last state).
long long stepsOf(const std::vector<Path>& paths) {
  long long steps = 0;
  for (const Path& p : paths) {
    std::size_t k = p.size();
    while (k > 1 && p[k - 2] == p[k - 1]) --k;
    steps += static_cast<long long>(k) - 1;
  }
  return steps;
}

}  // namespace

long long retimeToEarliest(const Instance& instance, Plan& plan, const ActionModel& model) {
  if (plan.paths.empty()) return 0;
  std::optional<std::vector<Path>> retimed;
  {
    const PlanCells cells(instance, plan, model);
    retimed = earliestSchedule(cells, buildStepDependencies(cells));
  }
  if (!retimed) return 0;
  const long long saved = stepsOf(plan.paths) - stepsOf(*retimed);
  plan.paths = std::move(*retimed);
  return saved;
}

}  // namespace fleet_planner
