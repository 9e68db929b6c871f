#include "fleet_planner/model/plan.h"

#include <algorithm>

namespace fleet_planner {

int pathCost(const Path& path, const GridPose& target) {
  if (path.empty() || path.back() != target) return -1;
  int t = static_cast<int>(path.size()) - 1;
  while (t > 0 && path[t - 1] == target) --t;
  return t;
}

PlanMetrics planMetrics(const Plan& plan, const std::vector<GridPose>& targets) {
  PlanMetrics m;
  for (std::size_t i = 0; i < plan.paths.size() && i < targets.size(); ++i) {
    const int cost = pathCost(plan.paths[i], targets[i]);
    if (cost < 0) return {-1, -1};
    m.soc += cost;
    m.makespan = std::max(m.makespan, cost);
  }
  if (plan.paths.size() != targets.size()) return {-1, -1};
  return m;
}

}  // namespace fleet_planner
