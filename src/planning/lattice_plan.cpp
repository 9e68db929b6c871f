// Assembling a full plan from a lattice plan and the robots' connections; see lattice.h.
#include <algorithm>
#include <numeric>

#include "fleet_planner/planning/lattice.h"

namespace fleet_planner {

namespace {

/// The cells a robot covers going from `from` to `to` in one step (relative to `from`).
const CellSet& sweepOf(const FootprintCells& cells, const GridPose& from, const GridPose& to) {
  if (from == to) return cells.body(from.heading);
  if (from.x == to.x && from.y == to.y) {
    return cells.swept(from.heading, kRotateCcw[from.heading] == to.heading ? Action::RotateCcw : Action::RotateCw);
  }
  const Cell d = kHeadingStep[from.heading];
  const bool forward = (to.x - from.x) * d.x + (to.y - from.y) * d.y > 0;
  return cells.moveSwept(from.heading, forward, moveLength(from, to));
}

const GridPose& at(const Path& p, int t) { return p[std::min<std::size_t>(static_cast<std::size_t>(t), p.size() - 1)]; }

/// Robot a following `pa` and robot b following `pb` meet at some step u >= from (a step's
/// sweeps overlap; after its path a robot stays at its last pose).
bool meet(const FootprintCells& ca, const Path& pa, const FootprintCells& cb, const Path& pb, int from) {
  const int end = static_cast<int>(std::max(pa.size(), pb.size()));
  for (int u = std::max(0, from); u < end; ++u) {
    const GridPose &a0 = at(pa, u), &a1 = at(pa, u + 1), &b0 = at(pb, u), &b1 = at(pb, u + 1);
    if (CellSet::overlap(sweepOf(ca, a0, a1), {a0.x, a0.y}, sweepOf(cb, b0, b1), {b0.x, b0.y})) return true;
  }
  // Both at rest from `end` on.
  const GridPose &a = pa.back(), &b = pb.back();
  return CellSet::overlap(ca.body(a.heading), {a.x, a.y}, cb.body(b.heading), {b.x, b.y});
}

}  // namespace

std::optional<Plan> assembleLatticePlan(const LatticeInstance& lattice, const FleetGraphs& graphs,
                                        const Plan& lattice_plan, std::string& problem) {
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
  for (int i : order) {
    const Path& suffix = lattice.connections[i].suffix;
    if (suffix.size() == 1) continue;
    const FootprintCells& ci = graphs.cells(i);
    bool placed = false;
    for (int t = arrival[i]; t <= horizon + static_cast<int>(suffix.size()) && !placed; ++t) {
      Path candidate(paths[i].begin(), paths[i].begin() + arrival[i] + 1);
      candidate.resize(static_cast<std::size_t>(t) + 1, candidate.back());
      candidate.insert(candidate.end(), suffix.begin() + 1, suffix.end());
      bool clash = false;
      for (int j = 0; j < n && !clash; ++j) {
        if (j != i) clash = meet(ci, candidate, graphs.cells(j), paths[j], t);
      }
      if (clash) continue;
      paths[i] = std::move(candidate);
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
