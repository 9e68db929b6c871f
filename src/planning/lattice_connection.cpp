// Putting a fleet on its planning lattice; see lattice.h.
#include <algorithm>
#include <cmath>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/planning/lattice.h"

namespace fleet_planner {

namespace {

/// The smaller extent of a footprint (cells).
double narrowWidth(const Footprint& f) {
  if (f.kind == Footprint::Kind::Circle) return 2.0 * f.radius;
  double min_x = 1e300, max_x = -1e300, min_y = 1e300, max_y = -1e300;
  for (const auto& p : f.outline()) {
    min_x = std::min(min_x, p.x()), max_x = std::max(max_x, p.x());
    min_y = std::min(min_y, p.y()), max_y = std::max(max_y, p.y());
  }
  return std::min(max_x - min_x, max_y - min_y);
}

int mod(int a, int s) { return ((a % s) + s) % s; }

/// One way to connect a robot: the heading it moves on to the lattice and the one it arrives on.
struct Choice {
  int cost = 0;
  Path prefix, suffix;
};

/// The poses of a short move of `k` cells from `p` along its heading (p excluded), if every one is
/// a valid state: then the move's sweep is free too (footprint_cells.h).
bool appendMove(const StateGraph& g, GridPose p, int k, Path& out) {
  const Cell d = kHeadingStep[p.heading];
  for (int j = 1; j <= k; ++j) {
    p = {p.x + d.x, p.y + d.y, p.heading};
    if (!g.valid(g.id(p))) return false;
  }
  if (k > 0) out.push_back(p);
  return true;
}

/// Appends a rotation from `p` to heading `h` (none if equal), if the graph allows it.
bool appendRotation(const StateGraph& g, const GridPose& p, int h, Path& out) {
  if (p.heading == h) return true;
  const Action a = kRotateCcw[p.heading] == h ? Action::RotateCcw : Action::RotateCw;
  if (!g.allows(g.id(p), a)) return false;
  out.push_back({p.x, p.y, h});
  return true;
}

/// Every valid way to connect robot `r`, cheapest first (ties in a fixed order).
std::vector<Choice> choicesFor(const Robot& r, const StateGraph& g, int s) {
  std::vector<Choice> out;
  const GridPose S = r.start, G = r.target;
  if (!g.valid(g.id(S)) || !g.valid(g.id(G))) return out;
  const int start_headings[] = {S.heading, kRotateCcw[S.heading], kRotateCw[S.heading]};
  // Headings from which at most one rotation reaches the target's.
  const int end_headings[] = {G.heading, kRotateCw[G.heading], kRotateCcw[G.heading]};
  for (int hc : start_headings) {
    for (int hf : end_headings) {
      const Cell dc = kHeadingStep[hc], df = kHeadingStep[hf];
      const bool c_on_x = dc.x != 0, f_on_x = df.x != 0;
      // Lengths (k at the start, kf at the target) that put both ends on one lattice.
      std::vector<std::pair<int, int>> lengths;
      if (c_on_x != f_on_x) {
        const int k = c_on_x ? mod((G.x - S.x) * dc.x, s) : mod((G.y - S.y) * dc.y, s);
        const int kf = f_on_x ? mod((G.x - S.x) * df.x, s) : mod((G.y - S.y) * df.y, s);
        lengths.push_back({k, kf});
      } else {
        const bool same_line = c_on_x ? mod(S.y - G.y, s) == 0 : mod(S.x - G.x, s) == 0;
        if (!same_line) continue;
        const int along = c_on_x ? G.x - S.x : G.y - S.y;
        lengths.push_back({mod(along * (c_on_x ? dc.x : dc.y), s), 0});
        lengths.push_back({0, mod(along * (f_on_x ? df.x : df.y), s)});
      }
      for (const auto& [k, kf] : lengths) {
        Choice c;
        c.prefix = {S};
        if (!appendRotation(g, S, hc, c.prefix) || !appendMove(g, c.prefix.back(), k, c.prefix)) continue;
        const Cell back = kHeadingStep[hf];
        const GridPose L{G.x - kf * back.x, G.y - kf * back.y, hf};
        c.suffix = {L};
        if (!g.valid(g.id(L)) || !appendMove(g, L, kf, c.suffix)) continue;
        if (!appendRotation(g, c.suffix.back(), G.heading, c.suffix)) continue;
        c.cost = static_cast<int>(c.prefix.size() + c.suffix.size()) - 2;
        out.push_back(std::move(c));
      }
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const Choice& a, const Choice& b) { return a.cost < b.cost; });
  return out;
}

/// A robot whose chosen connection collides (-1 if none), with the reason: the starts'
/// connections, run together, are checked by the validator; then each lattice target against
/// the other robots' lattice targets and targets.
int clash(const GridMap& map, const Instance& instance, const FleetGraphs& graphs,
          const std::vector<std::vector<Choice>>& choices, const std::vector<std::size_t>& chosen,
          const ActionModel& model, std::string& why) {
  const int n = static_cast<int>(instance.robots.size());
  std::size_t steps = 0;
  for (int i = 0; i < n; ++i) steps = std::max(steps, choices[i][chosen[i]].prefix.size());
  Plan prefixes;
  Instance connecting = instance;
  for (int i = 0; i < n; ++i) {
    Path p = choices[i][chosen[i]].prefix;
    connecting.robots[i].target = p.back();
    p.resize(steps, p.back());
    prefixes.paths.push_back(std::move(p));
  }
  const Violation v = validatePlan(map, connecting, prefixes, model).violation;
  if (v.kind != Violation::Kind::None) {
    why = v.message;
    return v.other >= 0 ? v.other : v.robot;  // the second robot named tries its next choice
  }
  for (int i = 0; i < n; ++i) {
    const GridPose& li = choices[i][chosen[i]].suffix.front();
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      const GridPose& lj = choices[j][chosen[j]].suffix.front();
      const GridPose& gj = instance.robots[j].target;
      const bool on_lattice_target = j > i && footprintsOverlap(graphs.cells(i), li, graphs.cells(j), lj);
      if (on_lattice_target || footprintsOverlap(graphs.cells(i), li, graphs.cells(j), gj)) {
        why = robotLabel(instance.robots[i]) + "'s lattice target " + toString(li) + " overlaps the " +
              (on_lattice_target ? "lattice target " + toString(lj) : "target " + toString(gj)) + " of " +
              robotLabel(instance.robots[j]);
        return i;
      }
    }
  }
  return -1;
}

}  // namespace

int defaultLatticeStep(const Instance& instance) {
  double narrowest = 1e300;
  for (const Robot& r : instance.robots) narrowest = std::min(narrowest, narrowWidth(r.footprint));
  if (instance.robots.empty() || !std::isfinite(narrowest)) return 1;
  return std::max(1, static_cast<int>(std::floor(narrowest / 3.0 + 1e-9)));
}

LatticeInstance connectToLattice(const GridMap& map, const Instance& instance, const FleetGraphs& graphs, int step) {
  LatticeInstance out;
  out.instance = instance;
  const int n = static_cast<int>(instance.robots.size());
  std::vector<std::vector<Choice>> choices(n);
  std::vector<std::size_t> chosen(n, 0);
  for (int i = 0; i < n; ++i) {
    choices[i] = choicesFor(instance.robots[i], graphs.graph(i), step);
    if (choices[i].empty()) {
      out.problem = robotLabel(instance.robots[i]) + " cannot reach a lattice of step " + std::to_string(step) +
                    " from its start or its target with one rotation and one short move";
      return out;
    }
  }
  // The starts' connections run together, and every lattice target must stay clear of the other
  // lattice targets and targets: re-choose for a robot whose connection breaks either.
  const ActionModel model = graphs.graph(0).actionModel();
  for (int round = 0;; ++round) {
    std::string why;
    const int who = clash(map, instance, graphs, choices, chosen, model, why);
    if (who < 0) break;
    if (++chosen[who] >= choices[who].size() || round > 9 * n) {
      out.problem = "the connections to a lattice of step " + std::to_string(step) + " collide: " + why;
      return out;
    }
  }
  out.connections.resize(n);
  for (int i = 0; i < n; ++i) {
    const Choice& c = choices[i][chosen[i]];
    out.connections[i] = {c.prefix, c.suffix};
    out.instance.robots[i].start = c.prefix.back();
    out.instance.robots[i].target = c.suffix.front();
  }
  return out;
}

}  // namespace fleet_planner
