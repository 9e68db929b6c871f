// Putting a fleet on its planning lattice; see lattice.h.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <thread>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/model/graph_search.h"
#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/model/instance_check.h"
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

/// A* expansions per connection choice for the robot's way on its lattice; a way not found
/// within them counts as kNoWay steps (the choice is tried last).
constexpr long long kWayExpansions = 200'000;
/// A* expansions for all robots' ways together (about a second).
constexpr long long kFleetWayExpansions = 10'000'000;
constexpr int kNoWay = 1 << 24;

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

/// The first map cell of `cells` (at `pose`) that is blocked or off the map, as "(x,y)"; empty if
/// none is.
std::string blockedCell(const GridMap& map, const CellSet& cells, const GridPose& pose) {
  for (const Cell& c : cells.cells()) {
    if (map.blocked(pose.x + c.x, pose.y + c.y)) {
      return "(" + std::to_string(pose.x + c.x) + "," + std::to_string(pose.y + c.y) + ")";
    }
  }
  return "";
}

/// The two grid headings within a quarter turn of `yaw`, the nearer first.
std::vector<int> headingsAround(double yaw) {
  std::vector<std::pair<double, int>> by_gap;
  for (int h = 0; h < kHeadings; ++h) {
    by_gap.push_back({std::abs(std::remainder(yaw - headingYaw(h), 2 * 3.141592653589793)), h});
  }
  std::sort(by_gap.begin(), by_gap.end());
  return {by_gap[0].second, by_gap[1].second};
}

/// One end's ways on or off the grid headings: poses at the end's cell, and the heading the
/// lattice side leaves or arrives on.
struct EndWay {
  Path poses;   ///< start side: from the start to (S, heading); target side: from (G, heading) on
  int heading;
};

/// The grid headings at `at`'s cell that a turn in place from (or, `to_yaw`, to) `yaw` can reach
/// or leave without touching a blocked cell, nearest first; with none, `why` names a blocked cell.
std::vector<int> turnableHeadings(const Robot& r, const StateGraph& g, const GridMap& map, const GridPose& at,
                                  double yaw, bool to_yaw, std::string& why) {
  std::vector<int> out;
  for (int h : headingsAround(yaw)) {
    const GridPose on{at.x, at.y, h};
    const CellSet sweep = to_yaw ? turnSweep(r.footprint, headingYaw(h), yaw) : turnSweep(r.footprint, yaw, headingYaw(h));
    const std::string hit = blockedCell(map, sweep, on);
    if (hit.empty() && g.valid(g.id(on))) {
      out.push_back(h);
    } else if (why.empty()) {
      why = std::string("turning in place ") + (to_yaw ? "to its target yaw" : "from its start yaw") +
            " covers the blocked cell " + (hit.empty() ? toString(on) : hit);
    }
  }
  return out;
}

/// The start's ways: a turn from the start yaw onto a heading near it (a step of its own), if any,
/// then at most one quarter turn. Empty, with `why`, if the start cannot turn at all.
std::vector<EndWay> startWays(const Robot& r, const StateGraph& g, const GridMap& map, std::string& why) {
  const GridPose& S = r.start;
  std::vector<EndWay> out;
  std::vector<Path> bases;
  if (r.start_yaw) {
    for (int h : turnableHeadings(r, g, map, S, *r.start_yaw, false, why)) bases.push_back({{S.x, S.y, h}, {S.x, S.y, h}});
  } else {
    bases.push_back({S});
  }
  for (const Path& base : bases) {
    const int h1 = base.back().heading;
    for (int hc : {h1, kRotateCcw[h1], kRotateCw[h1]}) {
      EndWay way{base, hc};
      if (appendRotation(g, base.back(), hc, way.poses)) out.push_back(std::move(way));
    }
  }
  return out;
}

/// The target's ways: arriving on a heading at most one quarter turn from the final heading,
/// then the turn to the target yaw (a step of its own), if any.
std::vector<EndWay> targetWays(const Robot& r, const StateGraph& g, const GridMap& map, std::string& why) {
  const GridPose& G = r.target;
  std::vector<EndWay> out;
  const std::vector<int> finals =
      r.target_yaw ? turnableHeadings(r, g, map, G, *r.target_yaw, true, why) : std::vector<int>{G.heading};
  for (int hg : finals) {
    for (int hf : {hg, kRotateCw[hg], kRotateCcw[hg]}) {
      EndWay way{{{G.x, G.y, hf}}, hf};
      if (!g.valid(g.id(way.poses[0])) || !appendRotation(g, way.poses[0], hg, way.poses)) continue;
      if (r.target_yaw) way.poses.push_back(way.poses.back());  // the step that turns to the yaw
      out.push_back(std::move(way));
    }
  }
  return out;
}

/// Every valid way to connect robot `r`, cheapest first (ties in a fixed order): on a lattice of
/// step > 1, the connecting steps plus the robot's way on the lattice they choose. `problem` is
/// set (with its kind) when an end has no way at all. Without `search_ways` (the fleet's budget
/// for them spent) the choices are in the order of their connecting steps alone. Adds the A*
/// expansions to `way_expansions`.
std::vector<Choice> choicesFor(const Robot& r, int index, const StateGraph& g, WaySearch& ways, const GridMap& map,
                               int s, bool search_ways, std::vector<RobotProblem>& problems,
                               long long& way_expansions) {
  std::vector<Choice> out;
  const GridPose S = r.start, G = r.target;
  std::string why;
  const std::vector<EndWay> starts = startWays(r, g, map, why);
  if (starts.empty()) {
    problems.push_back({index, -1, RobotProblem::Kind::InvalidStart, robotLabel(r) + ": start " + toString(S) + ": " +
                                                                       (why.empty() ? "no free state there" : why)});
    return out;
  }
  why.clear();
  const std::vector<EndWay> targets = targetWays(r, g, map, why);
  if (targets.empty()) {
    problems.push_back({index, -1, RobotProblem::Kind::InvalidTarget, robotLabel(r) + ": target " + toString(G) + ": " +
                                                                        (why.empty() ? "no free state there" : why)});
    return out;
  }
  for (const EndWay& start : starts) {
    for (const EndWay& target : targets) {
      const int hc = start.heading, hf = target.heading;
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
        if (s > 1) lengths.push_back({0, mod(along * (f_on_x ? df.x : df.y), s)});
        // Moves at both ends shift the lattice across that axis: any of its s offsets (a door
        // may be open on one of them only).
        for (int k = 1; k < s; ++k) {
          const int kf = mod((along - k * (c_on_x ? dc.x : dc.y)) * (f_on_x ? df.x : df.y), s);
          if (k != lengths.front().first) lengths.push_back({k, kf});  // else it is the first
        }
      }
      for (const auto& [k, kf] : lengths) {
        Choice c;
        c.prefix = start.poses;
        if (!appendMove(g, c.prefix.back(), k, c.prefix)) continue;
        const GridPose L{G.x - kf * df.x, G.y - kf * df.y, hf};
        c.suffix = {L};
        if (!g.valid(g.id(L)) || !appendMove(g, L, kf, c.suffix)) continue;
        c.suffix.insert(c.suffix.end(), target.poses.begin() + 1, target.poses.end());
        c.cost = static_cast<int>(c.prefix.size() + c.suffix.size()) - 2;
        out.push_back(std::move(c));
      }
    }
  }
  // On a coarser lattice the choice also sets the robot's offset, which may close a passage that
  // another offset keeps open (a door a little wider than the robot): each choice counts the
  // robot's way on its lattice, alone on the map, too (on step 1 every choice has the same).
  // Choices are searched in the order of a lower bound on that total (the connecting steps and
  // the moves of a straight way); one whose bound is no better than the best total found keeps
  // its bound, which sorts it after that best. Past the fleet's budget for these searches, the
  // robots left are ordered by connecting steps alone (deterministic: expansions, not time).
  if (s > 1 && search_ways) {
    for (Choice& c : out) c.cost += stepsBound(g, c.prefix.back(), c.suffix.front());
    std::stable_sort(out.begin(), out.end(), [](const Choice& a, const Choice& b) { return a.cost < b.cost; });
    std::map<std::pair<StateId, StateId>, int> known;
    int best = kNoWay;
    for (Choice& c : out) {
      if (c.cost >= best) break;
      const auto key = std::make_pair(g.id(c.prefix.back()), g.id(c.suffix.front()));
      auto it = known.find(key);
      if (it == known.end()) {
        const int way = ways.steps(g.id(c.prefix.back()), g.id(c.suffix.front()), kWayExpansions, way_expansions);
        it = known.emplace(key, way).first;
      }
      c.cost += (it->second >= 0 ? it->second : kNoWay) - stepsBound(g, c.prefix.back(), c.suffix.front());
      best = std::min(best, c.cost);
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
    connecting.robots[i].target_yaw.reset();
    p.resize(steps, p.back());
    prefixes.paths.push_back(std::move(p));
  }
  const Violation v = validatePlan(map, connecting, prefixes, model).violation;
  if (v.kind != Violation::Kind::None) {
    why = v.message;
    return v.other >= 0 ? v.other : v.robot;  // the second robot named tries its next choice
  }
  // Where each robot ends: its target's body (at its target yaw, if it has one).
  std::vector<CellSet> final_body(n);
  for (int j = 0; j < n; ++j) {
    const Robot& r = instance.robots[j];
    final_body[j] = r.target_yaw ? footprintCellsAt(r.footprint, *r.target_yaw) : graphs.cells(j).body(r.target.heading);
  }
  for (int i = 0; i < n; ++i) {
    const GridPose& li = choices[i][chosen[i]].suffix.front();
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      const GridPose& lj = choices[j][chosen[j]].suffix.front();
      const GridPose& gj = instance.robots[j].target;
      const bool on_lattice_target = j > i && footprintsOverlap(graphs.cells(i), li, graphs.cells(j), lj);
      if (on_lattice_target ||
          CellSet::overlap(graphs.cells(i).body(li.heading), {li.x, li.y}, final_body[j], {gj.x, gj.y})) {
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

LatticeInstance connectToLattice(const GridMap& map, const Instance& instance, const FleetGraphs& graphs, int step,
                                 int threads) {
  LatticeInstance out;
  out.instance = instance;
  const int n = static_cast<int>(instance.robots.size());
  // Each robot's choices, on `threads` workers (each with its own way searches; robots with
  // equal cells share a graph). The fleet's budget for the way searches is then counted in
  // the robots' order: a robot that one worker after the other would have reached with the
  // budget spent has its choices made again without them, so that the answer does not depend
  // on the threads.
  struct Made {
    std::vector<Choice> choices;
    std::vector<RobotProblem> problems;
    long long expansions = 0;
  };
  std::vector<Made> made(n);
  std::atomic<int> next{0};
  auto worker = [&] {
    std::map<const StateGraph*, WaySearch> ways;
    for (int i = next++; i < n; i = next++) {
      const StateGraph& g = graphs.graph(i);
      WaySearch& way = ways.try_emplace(&g, g).first->second;
      made[i].choices = choicesFor(instance.robots[i], i, g, way, map, step, true, made[i].problems, made[i].expansions);
    }
  };
  const int lanes = std::max(1, std::min(threads, n));
  std::vector<std::thread> pool;
  for (int t = 1; t < lanes; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  std::vector<std::vector<Choice>> choices(n);
  std::vector<std::size_t> chosen(n, 0);
  long long way_expansions = 0;
  for (int i = 0; i < n; ++i) {
    if (way_expansions >= kFleetWayExpansions) {
      const StateGraph& g = graphs.graph(i);
      WaySearch unused(g);
      made[i] = Made{};
      made[i].choices = choicesFor(instance.robots[i], i, g, unused, map, step, false, made[i].problems, made[i].expansions);
    }
    way_expansions += made[i].expansions;
    choices[i] = std::move(made[i].choices);
    if (!made[i].problems.empty()) {
      out.problems = std::move(made[i].problems);
      out.problem = out.problems.front().reason;
      return out;
    }
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
    out.instance.robots[i].start_yaw.reset();  // the lattice plan runs between grid poses
    out.instance.robots[i].target_yaw.reset();
  }
  return out;
}

}  // namespace fleet_planner
