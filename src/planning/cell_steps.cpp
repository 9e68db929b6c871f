// A lattice plan timed on the map's cells; see cell_steps.h.
#include "fleet_planner/planning/cell_steps.h"

#include <string>

#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

Plan onCellSteps(const Plan& plan, const ActionModel& model) {
  if (model.step <= 1) return plan;
  const int s = model.step;
  Plan out;
  out.paths.reserve(plan.paths.size());
  for (std::size_t i = 0; i < plan.paths.size(); ++i) {
    const Path& path = plan.paths[i];
    Path fine;
    if (path.empty()) {
      out.paths.push_back(fine);
      continue;
    }
    fine.reserve(path.size() * static_cast<std::size_t>(s));
    fine.push_back(path.front());
    for (std::size_t t = 0; t + 1 < path.size(); ++t) {
      const GridPose& from = path[t];
      const GridPose& to = path[t + 1];
      const auto action = actionBetween(from, to, model);
      if (!action) {
        throw InvalidInput("robot " + std::to_string(i) + ": step " + std::to_string(t) + " from " + toString(from) +
                           " to " + toString(to) + " is no motion on lattice step " + std::to_string(s));
      }
      int used = 1;
      if (*action == Action::Forward || *action == Action::Backward) {
        const Cell unit = kHeadingStep[from.heading];
        const int sign = *action == Action::Forward ? 1 : -1;
        used = moveLength(from, to);
        for (int k = 1; k <= used; ++k) fine.push_back({from.x + sign * k * unit.x, from.y + sign * k * unit.y, from.heading});
      } else {
        fine.push_back(to);
      }
      if (t + 2 < path.size()) fine.insert(fine.end(), static_cast<std::size_t>(s - used), to);
    }
    out.paths.push_back(std::move(fine));
  }
  return out;
}

}  // namespace fleet_planner
