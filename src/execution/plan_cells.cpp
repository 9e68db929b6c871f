// The cells a plan's robots occupy during execution; see plan_cells.h.
#include "fleet_planner/execution/plan_cells.h"

#include <algorithm>
#include <string>

#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

bool overlap(const PlacedCells& a, const PlacedCells& b) {
  const CellSet& p = *a.cells;
  const CellSet& q = *b.cells;
  if (p.empty() || q.empty()) return false;
  if (a.at.x + p.maxX() < b.at.x + q.minX() || b.at.x + q.maxX() < a.at.x + p.minX()) return false;
  if (a.at.y + p.maxY() < b.at.y + q.minY() || b.at.y + q.maxY() < a.at.y + p.minY()) return false;
  return CellSet::overlap(p, a.at, q, b.at);
}

PlanCells::PlanCells(const Instance& instance, const Plan& plan, const ActionModel& model, int from)
    : from_(std::max(from, 0)) {
  const std::size_t n = instance.robots.size();
  if (plan.paths.size() != n) {
    throw InvalidInput("plan has " + std::to_string(plan.paths.size()) + " paths for " + std::to_string(n) +
                       " robots");
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Robot& robot = instance.robots[i];
    const Path& path = plan.paths[i];
    if (path.empty()) throw InvalidInput(robotLabel(robot) + ": path is empty");
    paths_.push_back(&path);
    footprints_.push_back(sharedFootprintCells(robot.footprint, model.step));
    cells_.push_back(std::make_unique<RobotCells>(robot, *footprints_.back(), path));
    if (!cells_.back()->shapeProblem().empty())
      throw InvalidInput(robotLabel(robot) + ": " + cells_.back()->shapeProblem());
    const int steps = static_cast<int>(path.size()) - 1;
    std::vector<const CellSet*> sweeps(std::min(from_, std::max(steps, 0)), nullptr);
    std::vector<bool> moves(sweeps.size(), false);
    for (int t = static_cast<int>(sweeps.size()); t < steps; ++t) {
      const auto action = cells_.back()->actionAt(t, model);
      const CellSet* sweep = cells_.back()->sweepAt(t, model);
      if (!action || sweep == nullptr) {
        throw InvalidInput(robotLabel(robot) + ": step " + std::to_string(t) + " from " + toString(path[t]) +
                           " to " + toString(path[t + 1]) + " is no legal motion");
      }
      sweeps.push_back(sweep);
      moves.push_back(*action != Action::Wait);
    }
    sweeps_.push_back(std::move(sweeps));
    moves_.push_back(std::move(moves));
  }
}

PlacedCells PlanCells::atRest(int robot, int k) const {
  const GridPose& p = stateAt(*paths_[robot], k);
  return {&cells_[robot]->bodyAt(k), {p.x, p.y}};
}

PlacedCells PlanCells::during(int robot, int t) const {
  if (t >= lastState(robot)) return atRest(robot, t);
  const GridPose& p = stateAt(*paths_[robot], t);
  return {sweeps_[robot][t], {p.x, p.y}};
}

}  // namespace fleet_planner
