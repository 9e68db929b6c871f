// Assembling a full plan from a lattice plan and the robots' connections; see lattice.h.
#include <algorithm>
#include <memory>
#include <numeric>

#include "fleet_planner/model/robot_cells.h"
#include "fleet_planner/planning/lattice.h"

namespace fleet_planner {

bool pathsMeet(const RobotCells& a, const Path& pa, const RobotCells& b, const Path& pb, int from, const ActionModel& model) {
  const int end = static_cast<int>(std::max(pa.size(), pb.size()));
  // Robots farther apart than their reaches at the start of a step share no cell during it (a
  // step's sweep is within the reach of the cell it starts from). Such a step is not read, so a
  // step that is no legal motion counts as a meeting only when the robots are near: the paths
  // checked here are the planner's own, and the validator still checks every step.
  const int apart = a.reach() + b.reach();
  for (int u = std::max(0, from); u < end; ++u) {
    const GridPose &a0 = stateAt(pa, u), &b0 = stateAt(pb, u);
    if (fartherApart(a0, b0, apart)) continue;
    const CellSet* sa = a.sweepAt(u, model);
    const CellSet* sb = b.sweepAt(u, model);
    if (sa == nullptr || sb == nullptr) return true;  // not a motion: never taken as clear
    if (CellSet::overlap(*sa, {a0.x, a0.y}, *sb, {b0.x, b0.y})) return true;
  }
  const GridPose &a1 = pa.back(), &b1 = pb.back();
  return CellSet::overlap(a.bodyAt(end), {a1.x, a1.y}, b.bodyAt(end), {b1.x, b1.y});
}

std::optional<Plan> assembleLatticePlan(const Instance& instance, const LatticeInstance& lattice,
                                        const FleetGraphs& graphs, const Plan& lattice_plan, std::string& problem) {
  const std::vector<Robot>& original = instance.robots;
  std::vector<Robot> lattice_robots_with_start_yaw = original;
  for (Robot& r : lattice_robots_with_start_yaw) r.target_yaw.reset();
  const int n = static_cast<int>(lattice.connections.size());
  std::size_t prefix_poses = 1;
  for (const auto& c : lattice.connections) prefix_poses = std::max(prefix_poses, c.prefix.size());
  // Each robot: its start's connection (padded), then its lattice path.
  std::vector<Path> paths(n);
  std::vector<int> arrival(n);
  for (int i = 0; i < n; ++i) {
    Path p = lattice.connections[i].prefix;
    p.resize(prefix_poses, p.back());
    const Path& body = lattice_plan.paths[i];
    p.insert(p.end(), body.begin() + 1, body.end());
    arrival[i] = static_cast<int>(p.size()) - 1;
    paths[i] = std::move(p);
  }
  // Targets' connections, in order of arrival: the earliest start at which the connection and
  // the robot at rest after it meet nobody's motion (the robots not done yet stay on their
  // lattice targets as far as this one knows; their own connections are checked against it).
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return arrival[a] < arrival[b]; });
  int horizon = 0;
  for (const Path& p : paths) horizon = std::max(horizon, static_cast<int>(p.size()));
  // Each robot as the others see it: until its target's connection is placed it ends on its
  // lattice target, with no target yaw.
  const ActionModel model = graphs.graph(0).actionModel();
  std::vector<Robot> seen = lattice_robots_with_start_yaw;
  std::vector<std::unique_ptr<RobotCells>> cells(n);
  for (int j = 0; j < n; ++j) cells[j] = std::make_unique<RobotCells>(seen[j], graphs.cells(j), paths[j]);
  for (int i : order) {
    const Path& suffix = lattice.connections[i].suffix;
    if (suffix.size() == 1) continue;
    bool placed = false;
    // The robot's path if its connection starts at step t.
    auto connectedAt = [&](int t) {
      Path p(paths[i].begin(), paths[i].begin() + arrival[i] + 1);
      p.resize(static_cast<std::size_t>(t) + 1, p.back());
      p.insert(p.end(), suffix.begin() + 1, suffix.end());
      return p;
    };
    // Every candidate starts and ends on the same headings: its yaw shapes are computed once.
    const Path earliest = connectedAt(arrival[i]);
    const RobotCells shapes(original[i], graphs.cells(i), earliest);
    for (int t = arrival[i]; t <= horizon + static_cast<int>(suffix.size()) && !placed; ++t) {
      Path candidate = connectedAt(t);
      const RobotCells mine(original[i], shapes, candidate);
      bool clash = false;
      for (int j = 0; j < n && !clash; ++j) {
        if (j != i) clash = pathsMeet(mine, candidate, *cells[j], paths[j], t, model);
      }
      if (clash) continue;
      paths[i] = std::move(candidate);
      seen[i] = original[i];
      cells[i] = std::make_unique<RobotCells>(seen[i], shapes, paths[i]);
      horizon = std::max(horizon, static_cast<int>(paths[i].size()));
      placed = true;
    }
    if (!placed) {
      problem = robotLabel(lattice.instance.robots[i]) +
                ": the connection from its lattice target to its target is never clear of the other robots";
      return std::nullopt;
    }
  }
  return Plan{paths};
}

}  // namespace fleet_planner
