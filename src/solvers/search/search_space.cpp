#include "fleet_planner/solvers/search/search_space.h"

#include <atomic>
#include <set>
#include <thread>
#include <unordered_map>

#include "fleet_planner/model/contact_probe.h"
#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/runtime/resource_limits.h"

namespace fleet_planner {

namespace {

// Breadth-first from the target over reversed edges, straight into the agent's table (no
// 4-byte table of the whole map to scan and convert after). False (and an empty table) if the
// deadline passed: it is checked every 16384 states, a few hundred microseconds of work.
// `queue` is scratch.
bool restrictedDistances(const SearchSpace& space, int a, const Deadline& deadline, DistanceTable& table,
                         std::vector<StateId>& queue) {
  const StateGraph& g = space.graph(a);
  table.reset(static_cast<std::size_t>(g.stateIdCount()));
  const StateId target = space.target(a);
  if (!space.allows(a, target, Action::Wait)) return true;
  queue.assign(1, target);
  table.set(target, 0);
  for (std::size_t head = 0; head < queue.size(); ++head) {
    if ((head & 16383) == 16383 && deadline.expired()) {
      table = DistanceTable();
      return false;
    }
    const StateId s = queue[head];
    const int next = table[s] + 1;
    g.forEachPredecessor(s, [&](Action action, StateId prev) {
      if (!table.reached(prev) && space.allows(a, prev, action)) {
        table.set(prev, next);
        queue.push_back(prev);
      }
    });
  }
  return true;
}

// The sweep of `action` from `heading` outside the bodies before and after it; undecomposed
// when the sweep does not hold both bodies, or when those cells are not fewer than half of the
// sweep's `probe` (a block's turn: its corners' arcs), which is then the cheaper lookup.
SearchSpace::MoveExtra moveExtraOf(const FootprintCells& fc, int heading, Action action, const CellSet& probe) {
  SearchSpace::MoveExtra e;
  if (action == Action::Wait) return e;
  const Cell dir = kHeadingStep[heading];
  const int step = fc.step();
  Cell shift{0, 0};
  int after = heading;
  if (action == Action::Forward) shift = {dir.x * step, dir.y * step};
  if (action == Action::Backward) shift = {-dir.x * step, -dir.y * step};
  if (action == Action::RotateCcw) after = kRotateCcw[heading];
  if (action == Action::RotateCw) after = kRotateCw[heading];
  const CellSet& sweep = fc.swept(heading, action);
  const CellSet& before = fc.body(heading);
  const CellSet& then = fc.body(after);
  for (const Cell& c : before.cells()) {
    if (!sweep.contains(c.x, c.y)) return e;
  }
  for (const Cell& c : then.cells()) {
    if (!sweep.contains(c.x + shift.x, c.y + shift.y)) return e;
  }
  std::vector<Cell> rest;
  for (const Cell& c : sweep.cells()) {
    if (!before.contains(c.x, c.y) && !then.contains(c.x - shift.x, c.y - shift.y)) rest.push_back(c);
  }
  if (rest.size() * 2 > probe.size()) return e;
  e.decomposes = true;
  e.cells = CellSet::fromCells(std::move(rest));
  return e;
}

}  // namespace

SearchSpace::SearchSpace(const Subproblem& problem, bool distances)
    : instance_(problem.instance), graphs_(problem.graphs), robots_(problem.robots) {
  if (instance_ == nullptr || graphs_ == nullptr) throw InvalidInput("subproblem without instance or graphs");
  const int n = static_cast<int>(instance_->robots.size());
  if (graphs_->numRobots() != n) throw InvalidInput("subproblem graphs do not match its instance");
  std::set<int> seen;
  auto checkIndex = [&](int r, const char* what) {
    if (r < 0 || r >= n) throw InvalidInput(std::string(what) + " robot index " + std::to_string(r) + " out of range");
  };
  for (int r : robots_) {
    checkIndex(r, "subproblem");
    if (!seen.insert(r).second) throw InvalidInput("robot index " + std::to_string(r) + " listed twice");
  }
  for (const auto& b : problem.blocked) checkIndex(b.robot, "blocked footprint");
  for (const auto& m : problem.moving) checkIndex(m.robot, "moving obstacle");

  if (robots_.empty()) return;
  const StateGraph& g0 = graphs_->graph(robots_.front());
  if (!problem.blocked.empty()) {
    std::vector<std::uint8_t> cells(static_cast<std::size_t>(g0.width()) * g0.height(), 0);
    for (const auto& b : problem.blocked) {
      for (const Cell& c : graphs_->cells(b.robot).body(b.pose.heading).cells()) {
        const int x = b.pose.x + c.x, y = b.pose.y + c.y;
        if (x >= 0 && y >= 0 && x < g0.width() && y < g0.height()) cells[static_cast<std::size_t>(y) * g0.width() + x] = 1;
      }
    }
    static_cells_ = std::make_unique<ObstacleIndex>(GridMap(g0.width(), g0.height(), std::move(cells)),
                                                    ObstacleIndex::Clearance::Chessboard);
    has_static_ = true;
  }
  if (!problem.moving.empty()) {
    reservations_ = ReservationTable(g0.width(), g0.height(), problem.moving, *graphs_, g0.actionModel());
  }
  makeLookups();

  for (int a = 0; a < numAgents(); ++a) {
    const Robot& r = instance_->robots[robots_[a]];
    GridPose start = r.start, target = r.target;
    for (const StaticFootprint& back : problem.returning) {
      if (back.robot == robots_[a]) start = target = back.pose;
    }
    starts_.push_back(graph(a).id(start));
    targets_.push_back(graph(a).id(target));
  }
  distances_.resize(numAgents());
  const MemoryGuard* guard = problem.deadline.memoryGuard();
  if (guard && distances) {
    guard->reserve(static_cast<double>(numAgents()) * static_cast<double>(distanceTableBytes(
                                                          static_cast<long long>(g0.width()) * g0.height())) /
                       1048576.0,
                   "the distance tables of " + std::to_string(numAgents()) + " robots");
  }
  // The first agent (in order) with a start or target that is not a valid free state; the
  // distance tables of the agents before it (when asked for), on `problem.threads` threads; the
  // first of those whose target cannot be reached from its start, if any, else that agent, is
  // the problem: what one agent after the other would find.
  int invalid = numAgents();
  for (int a = 0; a < numAgents() && invalid == numAgents(); ++a) {
    const std::string why = endpointProblem(a);
    if (!why.empty()) {
      invalid = a;
      problem_ = why;
    }
  }
  if (!distances) return;
  std::atomic<int> next{0};
  std::atomic<bool> expired{false};
  auto worker = [&] {
    std::vector<StateId> queue;
    for (int a = next++; a < invalid; a = next++) {
      // One table per agent: on large maps and fleets, seconds.
      if (expired || problem.deadline.expired() ||
          !restrictedDistances(*this, a, problem.deadline, distances_[a], queue)) {
        expired = true;
        return;
      }
    }
  };
  const int lanes = std::max(1, std::min(problem.threads, invalid));
  std::vector<std::thread> pool;
  for (int t = 1; t < lanes; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (expired) {
    stopped_ = true;
    return;
  }
  for (int a = 0; a < invalid; ++a) {
    if (distances_[a][starts_[a]] < 0) {
      problem_ = label(a) + ": target " + toString(graph(a).pose(targets_[a])) + " is not reachable from start " +
                 toString(graph(a).pose(starts_[a]));
      return;
    }
  }
}

bool SearchSpace::buildDistances(int a, const Deadline& deadline) {
  std::vector<StateId> queue;
  return restrictedDistances(*this, a, deadline, distances_[a], queue);
}

void SearchSpace::makeLookups() {
  // The pitch: the side of the largest square every body holds (a sweep holds its start's
  // body), and the reservations' pitch; 1 (every cell) unless every sweep is 4-connected.
  int pitch = reservations_.contactPitch();
  for (int a = 0; a < numAgents() && pitch > 1; ++a) {
    const FootprintCells& fc = cells(a);
    for (int h = 0; h < kHeadings; ++h) {
      pitch = std::min(pitch, largestSquare(fc.body(h)));
      for (int act = 0; act < kActions; ++act) {
        if (!fourConnected(fc.swept(h, static_cast<Action>(act)))) pitch = 1;
      }
    }
  }
  pitch = std::max(pitch, 1);
  // Agents with the same cells share their lookups.
  std::unordered_map<const FootprintCells*, std::shared_ptr<const Lookups>> made;
  lookups_.resize(numAgents());
  for (int a = 0; a < numAgents(); ++a) {
    std::shared_ptr<const Lookups>& shared = made[&cells(a)];
    if (!shared) {
      auto l = std::make_shared<Lookups>();
      const FootprintCells& fc = cells(a);
      for (int h = 0; h < kHeadings; ++h) {
        for (int act = 0; act < kActions; ++act) {
          const Action action = static_cast<Action>(act);
          l->probes[h][act] = contactProbe(fc.swept(h, action), pitch);
          l->extras[h][act] = moveExtraOf(fc, h, action, l->probes[h][act]);
        }
        l->turns_back_alike[h][0] = fc.swept(h, Action::RotateCcw) == fc.swept(kRotateCcw[h], Action::RotateCw);
        l->turns_back_alike[h][1] = fc.swept(h, Action::RotateCw) == fc.swept(kRotateCw[h], Action::RotateCcw);
        l->same_wait[h] = h;
        for (int g = 0; g < h && l->same_wait[h] == h; ++g) {
          if (fc.body(g) == fc.body(h) && fc.swept(g, Action::Wait) == fc.swept(h, Action::Wait)) l->same_wait[h] = g;
        }
      }
      shared = std::move(l);
    }
    lookups_[a] = shared;
  }
}

std::string SearchSpace::endpointProblem(int a) const {
  GridPose start = instance_->robots[robots_[a]].start, target = instance_->robots[robots_[a]].target;
  if (graph(a).valid(starts_[a])) start = graph(a).pose(starts_[a]);
  if (graph(a).valid(targets_[a])) target = graph(a).pose(targets_[a]);
  if (!graph(a).valid(starts_[a])) return label(a) + ": start " + toString(start) + " is not a valid state";
  if (!graph(a).valid(targets_[a])) return label(a) + ": target " + toString(target) + " is not a valid state";
  if (!allows(a, starts_[a], Action::Wait))
    return label(a) + ": start " + toString(start) + " overlaps a footprint of another subproblem";
  if (!allows(a, targets_[a], Action::Wait))
    return label(a) + ": target " + toString(target) + " overlaps a footprint of another subproblem";
  return "";
}

std::string SearchSpace::label(int a) const { return "robot '" + instance_->robots[robots_[a]].id + "'"; }

}  // namespace fleet_planner
