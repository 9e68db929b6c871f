#pragma once
// One robot at a time, the robots in its way pushed into pockets (parking_plan.h): the state of
// one parking plan, private to parking_plan.cpp, which runs it in one order or in several.
#include <algorithm>
#include <deque>
#include <functional>
#include <memory>
#include <queue>

#include "fleet_planner/model/action.h"
#include "fleet_planner/solvers/lns/parking_plan.h"
#include "fleet_planner/solvers/lns/pocket_repair.h"
#include "fleet_planner/solvers/search/safe_interval_search.h"
#include "fleet_planner/solvers/search/soft_path_table.h"
#include "fleet_planner/solvers/search/touched_array.h"

namespace fleet_planner {

class Parking {
 public:
  // `beaten(spent)`: another order has already done better than this one can (see
  // fastestParkingPlan); the plan then stops where it is.
  Parking(const SearchSpace& space, const Deadline& deadline, const ParkingPlanOptions& options,
          std::function<bool(long long)> beaten = {})
      : space_(space),
        deadline_(deadline),
        options_(options),
        beaten_(std::move(beaten)),
        n_(space.numAgents()),
        table_(space),
        paths_(n_),
        queued_(n_, 0),
        reaches_home_(n_) {
    for (int a = 0; a < n_; ++a) {
      paths_[a] = {space.start(a)};
      table_.insert(a, paths_[a]);
    }
    pocket_options_.max_pockets = options.max_pockets;
    pocket_options_.around_final_states = true;
  }

  std::optional<ParkingPlan> run(const std::vector<int>& order) {
    start(order);
    while (turn()) {
    }
    return finish();
  }

  // Robots take their turns in `order`.
  void start(const std::vector<int>& order) {
    for (int a : order) {
      if (space_.start(a) != space_.target(a)) enqueue(a);
    }
    failed_.assign(n_, 0);
  }

  // The next robot's turn; false (nothing done) once every robot is home or given up, or the
  // budget, the deadline or a better order (`beaten`) has ended the plan.
  bool turn() {
    if (queue_.empty() || outOfBudget()) return false;
    const int a = queue_.front();
    queue_.pop_front();
    queued_[a] = 0;
    // Its way through fewest standing robots: if it meets none, a safe interval search
    // drives it home (around the robots that still move); otherwise, or if that fails, the
    // robots on it drive into pockets off it first.
    int blocked_steps = 0;
    const StatePath through = cheapestWay(
        a, paths_[a].back(), [&](StateId s) { return s == space_.target(a); }, true, nullptr,
        &blocked_steps);
    if (blocked_steps == 0 && driveTo(a, space_.target(a))) return true;
    // Given up: it stays where it stands (others may still push it).
    if (++failed_[a] > options_.max_failed_turns || through.empty()) return true;
    std::vector<char> way;
    markWay(space_, a, through, way);
    std::vector<char> busy(n_, 0);
    busy[a] = 1;
    const int pushed = clear(way, busy, options_.push_depth);
    if (pushed > 0) {
      queue_.push_front(a);
    } else {
      queue_.push_back(a);
    }
    queued_[a] = 1;
    return true;
  }

  // The plan as far as it got; none if it has a conflict (a defect).
  std::optional<ParkingPlan> finish() {
    if (firstConflict(space_, paths_)) return std::nullopt;
    ParkingPlan plan;
    plan.home.assign(n_, 0);
    for (int a = 0; a < n_; ++a) {
      plan.home[a] = paths_[a].back() == space_.target(a);
      plan.robots_home += plan.home[a];
    }
    plan.paths = std::move(paths_);
    return plan;
  }

  long long spent() const { return spent_; }
  bool gaveWay() const { return gave_way_; }

 private:
  bool outOfBudget() const {
    if (beaten_ && !gave_way_ && beaten_(spent_)) gave_way_ = true;
    return gave_way_ || deadline_.expired() || spent_ >= options_.max_expansions;
  }
  void enqueue(int a) {
    if (queued_[a]) return;
    queue_.push_back(a);
    queued_[a] = 1;
  }

  // Agent b's footprint where its path ends meets a cell of `way`.
  bool standsOn(int b, const std::vector<char>& way) const {
    return !clearOfWay(space_, b, paths_[b].back(), way);
  }

  // Agent a doing `action` from s meets a robot of another subproblem that has parked for good.
  bool parkedForGood(int a, StateId s, Action action) const {
    const ReservationTable& reservations = space_.reservations();
    if (reservations.empty()) return false;
    const GridPose p = space_.graph(a).pose(s);
    return reservations.taken(space_.probe(a, p.heading, action), {p.x, p.y},
                              reservations.lastChange() + 1);
  }

  // Agent a doing `action` from s meets another agent where that one's path ends: 0 no, 1 yes,
  // 2 one marked in `busy` (if given).
  int crowded(int a, StateId s, Action action = Action::Wait,
              const std::vector<char>* busy = nullptr) const {
    met_.clear();
    table_.collisionsAtEnd(a, s, action, met_);
    return crowdOf(busy);
  }
  // What crowded() says of the robots met_ holds.
  int crowdOf(const std::vector<char>* busy) const {
    if (busy && std::any_of(met_.begin(), met_.end(), [&](int b) { return (*busy)[b] != 0; }))
      return 2;
    return met_.empty() ? 0 : 1;
  }

  // crowded(a, s, action, busy) for a move to `next`: a move that decomposes
  // (SearchSpace::moveExtra) meets a robot iff its body before, its body after or its extra
  // cells do, and the bodies' answers are kept in `waits` (-1: not asked yet), so that a
  // state's neighbours ask its body once.
  int crowdedMove(int a, StateId s, Action action, StateId next, const std::vector<char>* busy,
                  TouchedArray<int>& waits) const {
    const GridPose p = space_.graph(a).pose(s);
    const CellSet* extra = space_.moveExtra(a, p.heading, action);
    if (extra == nullptr) return crowded(a, s, action, busy);
    int crowd = 0;
    for (StateId q : {s, next}) {
      if (waits[q] < 0) waits.set(q, crowded(a, q, Action::Wait, busy));
      crowd = std::max(crowd, waits[q]);
    }
    if (crowd == 2 || extra->empty()) return crowd;
    met_.clear();
    table_.collisionsAtEnd(a, *extra, {p.x, p.y}, met_);
    return std::max(crowd, crowdOf(busy));
  }

  // Agent a's way from `from` to the first state `goal` accepts, among the static obstacles
  // and the robots of other subproblems parked for good. With `crowds`, cheapest when a state
  // among robots standing where their paths end costs options.crowd_cost steps more (moves
  // through a robot marked in `busy` are barred). A* with a's distances as the heuristic when
  // `to_target` (the goal is its target), else Dijkstra: for other goals the distance to the
  // target is no lower bound. Empty if no way within options.max_way_states.
  StatePath cheapestWay(int a, StateId from, const std::function<bool(StateId)>& goal,
                        bool to_target, const std::vector<char>* busy = nullptr,
                        int* blocked_steps = nullptr, bool crowds = true) const {
    const StateGraph& g = space_.graph(a);
    // Its goal may search again (reachesHome): one scratch per depth.
    if (way_depth_ == way_scratch_.size()) way_scratch_.push_back(std::make_unique<WayScratch>());
    WayScratch& scratch = *way_scratch_[way_depth_++];
    struct Leave {
      std::size_t& depth;
      ~Leave() { --depth; }
    } leave{way_depth_};
    TouchedArray<int>& cost = scratch.cost;
    cost.reset(static_cast<std::size_t>(g.stateIdCount()), -1);
    scratch.crowd.reset(static_cast<std::size_t>(g.stateIdCount()), -1);
    std::vector<StateId>& parent = scratch.parent;  // read only where cost is set
    parent.resize(static_cast<std::size_t>(g.stateIdCount()));
    parent[from] = kNoState;
    using Entry = std::pair<long long, StateId>;  // (f, state)
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    auto h = [&](StateId s) { return to_target ? space_.distance(a, s) : 0; };
    cost.set(from, 0);
    open.push({h(from), from});
    long long popped = 0;
    while (!open.empty() && popped++ < options_.max_way_states) {
      const auto [f, s] = open.top();
      open.pop();
      if (f != cost[s] + h(s)) continue;
      if (goal(s) && space_.distance(a, s) >= 0) {
        StatePath way;
        for (StateId q = s; q != kNoState; q = parent[q]) way.push_back(q);
        std::reverse(way.begin(), way.end());
        if (blocked_steps)
          *blocked_steps = (cost[s] - static_cast<int>(way.size()) + 1) / options_.crowd_cost;
        return way;
      }
      g.forEachSuccessor(s, [&](Action act, StateId next) {
        if (space_.distance(a, next) < 0 || !space_.allows(a, s, act) || parkedForGood(a, s, act))
          return;
        // Reached as cheaply already whatever the crowd (the way back of a turn, mostly): the
        // crowd is not looked up.
        if (cost[next] >= 0 && cost[next] <= cost[s] + 1) return;
        const int crowd = crowds ? crowdedMove(a, s, act, next, busy, scratch.crowd) : 0;
        if (crowd == 2) return;  // through a robot that is not to be pushed
        const int c = cost[s] + 1 + (crowd ? options_.crowd_cost : 0);
        if (cost[next] >= 0 && cost[next] <= c) return;
        cost.set(next, c);
        parent[next] = s;
        open.push({c + h(next), next});
      });
    }
    return {};
  }

  // Agent b can drive from s to its target around the robots of other subproblems parked for
  // good (its distances account for the static obstacles only: without reversing, a pocket
  // facing a parked robot with no room to turn is a trap). Cached per state.
  bool reachesHome(int b, StateId s) {
    if (space_.reservations().empty()) return true;
    std::vector<char>& known = reaches_home_[b];  // 0 unknown, 1 yes, 2 no
    if (known.empty()) known.assign(static_cast<std::size_t>(space_.graph(b).stateIdCount()), 0);
    if (known[s] == 0) {
      const StatePath home = cheapestWay(
          b, s, [&](StateId q) { return q == space_.target(b) || known[q] == 1; }, true, nullptr,
          nullptr, false);
      if (home.empty()) known[s] = 2;
      for (StateId q : home) known[q] = 1;
    }
    return known[s] == 1;
  }

  // The robots standing on `way` (and not busy) drive into pockets off it; a robot with no
  // pocket it can reach first has the robots on its way to the nearest pocket pushed off
  // that (up to `depth` times over). Returns how many were pushed.
  int clear(const std::vector<char>& way, std::vector<char>& busy, int depth) {
    int pushed = 0;
    for (int b = 0; b < n_ && !outOfBudget(); ++b) {
      if (busy[b] || !standsOn(b, way)) continue;
      bool parked = park(b, way);
      if (!parked && depth > 0) {
        busy[b] = 1;
        const StatePath route = cheapestWay(
            b, paths_[b].back(), [&](StateId s) { return offWay(b, s, way) && reachesHome(b, s); },
            false, &busy);
        busy[b] = 0;
        if (route.size() < 2) continue;
        std::vector<char> wider = way;
        markWay(space_, b, route, wider);
        busy[b] = 1;
        pushed += clear(wider, busy, depth - 1);
        busy[b] = 0;
        parked = driveTo(b, route.back()) || park(b, way);
      }
      if (!parked) continue;
      ++pushed;
      if (paths_[b].back() != space_.target(b)) enqueue(b);  // it comes back later
    }
    return pushed;
  }

  // b may park at s for good: off the way, clear of every final state.
  bool offWay(int b, StateId s, const std::vector<char>& way) const {
    return clearOfWay(space_, b, s, way) && !crowded(b, s);
  }

  // Agent b drives from where its path ends to the first of its pockets off `way` it reaches.
  bool park(int b, const std::vector<char>& way) {
    table_.remove(b);
    const std::vector<StateId> pockets =
        pocketsOffWay(space_, b, table_, way, pocket_options_, paths_[b].back());
    table_.insert(b, paths_[b]);
    for (StateId pocket : pockets) {
      if (outOfBudget()) return false;
      if (reachesHome(b, pocket) && driveTo(b, pocket)) return true;
    }
    return false;
  }

  // Agent a's path extended from its end to `to` (its target, held for good; or a pocket),
  // collision-free around everybody else; false (the path as it was) if there is none within
  // the budget. A pocket is reached at the earliest if nobody passes it later, else at the
  // earliest after the last pass over it (safeIntervalPocket), so that neither this leg nor
  // the robot's later turns wait for the rest of the plan to end.
  bool driveTo(int a, StateId to) {
    const StateId from = paths_[a].back();
    if (from == to) return to == space_.target(a);
    const int t0 = static_cast<int>(paths_[a].size()) - 1;
    table_.remove(a);
    bool ok = false;
    if (to == space_.target(a)) {
      ok = leg(a, t0, to, Arrival::Home);
    } else {
      ok = leg(a, t0, to, Arrival::Earliest);
      if (!ok && last_outcome_ == SafeIntervalResult::Outcome::Found) ok = leg(a, t0, to, Arrival::HeldForGood);
    }
    table_.insert(a, paths_[a]);
    return ok;
  }

  // How a leg arrives: home (held for good), at a pocket at the earliest, or at a pocket held
  // for good from its arrival.
  enum class Arrival { Home, Earliest, HeldForGood };

  // One safe interval search from where a's path ends, at step t0; its path appended to a's
  // (out of the table) if the pose it ends at is free for good.
  bool leg(int a, int t0, StateId to, Arrival arrival_kind) {
    const StateId from = paths_[a].back();
    const long long budget = options_.max_expansions - spent_;
    const SafeIntervalResult found =
        arrival_kind == Arrival::Home ? safeIntervalHome(space_, a, table_, from, t0, deadline_, budget)
        : arrival_kind == Arrival::HeldForGood
            ? safeIntervalPocket(space_, a, table_, from, t0, to, deadline_, budget)
            : safeIntervalSegment(space_, a, table_, from, t0, to, t0, SoftPathTable::kNever / 2, deadline_, budget);
    spent_ += found.expansions;
    last_outcome_ = found.outcome;
    if (found.outcome != SafeIntervalResult::Outcome::Found || found.path.empty() ||
        found.path.front() != from)
      return false;
    const int arrival = t0 + static_cast<int>(found.path.size()) - 1;
    if (to != space_.target(a)) {
      met_.clear();
      table_.collisionsHolding(a, to, arrival, met_);
      if (!met_.empty() || !freeForGood(a, to, arrival)) return false;
    }
    paths_[a].pop_back();
    paths_[a].insert(paths_[a].end(), found.path.begin(), found.path.end());
    return true;
  }

  // No other subproblem's timed path reaches state s of agent a from step `parked` on.
  bool freeForGood(int a, StateId s, int parked) const {
    const ReservationTable& reservations = space_.reservations();
    if (reservations.empty()) return true;
    const GridPose p = space_.graph(a).pose(s);
    std::vector<std::pair<int, int>> taken;
    reservations.takenIntervals(space_.probe(a, p.heading, Action::Wait), {p.x, p.y}, taken);
    return std::all_of(taken.begin(), taken.end(),
                       [&](const auto& run) { return run.second < parked; });
  }

  const SearchSpace& space_;
  const Deadline& deadline_;
  const ParkingPlanOptions& options_;
  const std::function<bool(long long)> beaten_;
  mutable bool gave_way_ = false;
  const int n_;
  SoftPathTable table_;
  std::vector<StatePath> paths_;
  std::deque<int> queue_;
  std::vector<char> queued_;
  std::vector<int> failed_;  // turns without a path home, per agent
  std::vector<std::vector<char>> reaches_home_;
  PocketRepairOptions pocket_options_;
  long long spent_ = 0;
  mutable std::vector<int> met_;
  struct WayScratch {
    TouchedArray<int> cost, crowd;
    std::vector<StateId> parent;
  };
  mutable std::vector<std::unique_ptr<WayScratch>> way_scratch_;  // cheapestWay's, by depth
  mutable std::size_t way_depth_ = 0;
  SafeIntervalResult::Outcome last_outcome_ = SafeIntervalResult::Outcome::NoPath;
};

}  // namespace fleet_planner
