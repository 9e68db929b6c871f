#include "fleet_planner/solvers/search/safe_interval_search.h"

#include <algorithm>
#include <cstdlib>
#include <memory>

#include "sipp_answers.h"
#include "sipp_memory.h"

namespace fleet_planner {

thread_local std::unique_ptr<sipp_detail::SearchMemory> sipp_detail::MemoryLease::idle_;

namespace {

using namespace sipp_detail;

// Lower bound on the steps from s to `goal`: a move changes one coordinate by the lattice step
// (ActionModel::step cells), and a different heading takes at least one rotation.
int stepsBetween(const StateGraph& g, StateId s, StateId goal) {
  const GridPose p = g.pose(s), q = g.pose(goal);
  const int step = g.actionModel().step;
  return (std::abs(p.x - q.x) + step - 1) / step + (std::abs(p.y - q.y) + step - 1) / step +
         (p.heading != q.heading ? 1 : 0);
}

// The earliest arrival within `interval` of a state, for a search from step t0: an interval
// that begins after t0 follows a step during which the state's body meets someone, and so
// does every move into it during that step.
int arrivalFor(const Interval& interval, int t0) {
  return interval.first > t0 ? interval.first + 1 : interval.first;
}

// Earliest-arriving collision-free way of agent a from `from` at step t0 to `goal`: held for
// good (t1 == kNever; `goal` is then a's target; or `hold`: any goal, t1 unused), or reached
// by step t1 and held until t1, or reached later, by step t1 + max_delay.
// Held for good, arrivals after `max_arrival` are not searched; with `wait_first` too, the
// search first departs late where the agent can wait (safeIntervalHome), then, if that finds
// nothing, from t0, its intervals kept.
SafeIntervalResult searchBetween(const SearchSpace& space, int a, const SoftPathTable& others,
                                 StateId from, int t0, StateId goal, int t1, int max_delay,
                                 const Deadline& deadline, long long max_expansions,
                                 int max_arrival = kNever, double weight = 1.0,
                                 bool wait_first = false, bool hold = false) {
  SafeIntervalResult result;
  const StateGraph& g = space.graph(a);
  if (space.distance(a, from) < 0) return result;
  const bool to_target = t1 == kNever;
  const bool forever = to_target || hold;
  // The distances are to the target: any other goal has the lower bound of its steps.
  auto heuristic = [&](StateId s) {
    return to_target ? space.distance(a, s) : stepsBetween(g, s, goal);
  };
  MemoryLease lease(g.stateIdCount());
  SearchMemory& memory = lease.memory();
  Sipp sipp(space, a, others, t0, memory);
  const int from_answers = sipp.intervalsOf(from);
  const PoolRun<Interval> first = sipp.answers(from_answers).intervals;
  int first_interval = -1;
  for (int i = 0; i < static_cast<int>(first.size()) && first_interval < 0; ++i) {
    if (first[i].first <= t0 && (first[i].last == kNever || t0 <= first[i].last)) first_interval = i;
  }
  if (first_interval < 0) return result;  // someone sweeps `from` at t0
  // The late departure: kHomeLeadSteps plus twice the distance before the goal is free for
  // good (`ready`), if the agent can wait at `from` until then; arrivals bounded by
  // kHomeLeadSteps plus the distance after `ready`.
  int late = t0, late_bound = max_arrival;
  const PoolRun<Interval> home = forever ? sipp.intervals(goal) : PoolRun<Interval>{};
  // Held for good, the goal's last safe interval is the only one to arrive in: none if it
  // never is free for good, or only after max_arrival.
  if (forever && (home.empty() || home.back().last != kNever || arrivalFor(home.back(), t0) > max_arrival))
    return result;
  if (wait_first && home.back().first > t0) {
    const int d = heuristic(from), ready = home.back().first;
    const int depart = ready - 2 * d - kHomeLeadSteps, last = first[first_interval].last;
    if (depart > t0 && (last == kNever || last >= depart)) {
      late = depart;
      late_bound = std::min(max_arrival, ready + d + kHomeLeadSteps);
    }
  }
  int bound = late_bound;

  std::vector<Node>& nodes = memory.nodes;
  auto worse = [](const SearchMemory::Open& p, const SearchMemory::Open& q) {
    if (p.f != q.f) return p.f > q.f;
    if (p.g != q.g) return p.g < q.g;
    return p.index > q.index;
  };
  std::vector<SearchMemory::Open>& open = memory.open;  // a heap: the node to expand next in front
  // A node of (s, interval) arriving at `arrival`, unless one arrives there as early already; a
  // later one it replaces is marked stale (skipped when it comes off the heap). `answers`: the
  // index of s's answers (Sipp::intervalsOf).
  auto push = [&](StateId s, int answers, int interval, int last, int arrival, int parent) {
    const int h = heuristic(s);
    if (arrival + h > (forever ? bound : t1 + max_delay)) return;  // cannot reach the goal in time
    const int f = weight == 1.0 ? arrival + h : arrival + static_cast<int>(weight * h);
    int& entry = sipp.bestNode(answers, interval);
    if (entry >= 0) {
      if (nodes[entry].g <= arrival) return;
      nodes[entry].stale = true;
    }
    entry = static_cast<int>(nodes.size());
    nodes.push_back({s, interval, last, arrival, f, parent, false});
    open.push_back({f, arrival, static_cast<int>(nodes.size()) - 1});
    std::push_heap(open.begin(), open.end(), worse);
  };
  // One pass from the late departure, if any, then (if it found nothing) one from t0.
  for (int pass = late != t0 ? 0 : 1; pass < 2; ++pass) {
    const int begin = pass == 0 ? late : t0;
    bound = pass == 0 ? late_bound : max_arrival;
    nodes.clear();
    sipp.forgetNodes();
    open.clear();
    push(from, from_answers, first_interval, first[first_interval].last, begin, -1);
    while (!open.empty()) {
      if ((result.expansions & 255) == 0 && deadline.expired()) {
        result.outcome = SafeIntervalResult::Outcome::Expired;
        return result;
      }
      if (result.expansions >= max_expansions) {
        result.outcome = SafeIntervalResult::Outcome::NodeLimit;
        return result;
      }
      const int index = open.front().index;
      std::pop_heap(open.begin(), open.end(), worse);
      open.pop_back();
      const Node node = nodes[index];
      if (node.stale) continue;
      ++result.expansions;
      // Finite t1: the agent can wait here until t1 (an arrival after t1 lies in its interval).
      const bool arrived = forever ? node.last == kNever : node.last >= t1 - 1;
      if (node.s == goal && arrived) {
        std::vector<int> chain;
        for (int i = index; i >= 0; i = nodes[i].parent) chain.push_back(i);
        std::reverse(chain.begin(), chain.end());
        for (std::size_t k = 0; k < chain.size(); ++k) {
          const Node& n = nodes[chain[k]];
          const int until = k + 1 < chain.size() ? nodes[chain[k + 1]].g
                            : forever                ? n.g + 1
                                                     : std::max(t1, n.g) + 1;
          for (int t = n.g; t < until; ++t) result.path.push_back(n.s);
        }
        result.path.insert(result.path.begin(), static_cast<std::size_t>(begin - t0), from);  // its wait
        result.outcome = SafeIntervalResult::Outcome::Found;
        return result;
      }
      g.forEachSuccessor(node.s, [&](Action act, StateId next) {
        if (act == Action::Wait || space.distance(a, next) < 0 || !space.allows(a, node.s, act))
          return;
        const int next_answers = sipp.intervalsOf(next);
        const PoolRun<Interval> there = sipp.answers(next_answers).intervals;
        // A move that decomposes (SearchSpace::moveExtra) collides during step t iff waiting at
        // node.s or at next during t does, or its extra cells meet someone then. Departing at t
        // within node's interval and arriving at t + 1 within there[j] (t + 1 <= there[j].last) leaves
        // only t = there[j].first - 1 to the body after, always unsafe when it is a step of the
        // search (the interval begins after an unsafe step): the departures from
        // there[j].first on, against the extra cells alone.
        const CellSet* extra = space.moveExtra(a, g.pose(node.s).heading, act);
        Unsafe move;
        bool known = false;  // the move's unsafe steps are read only if some interval of next may be reached
        // The first interval of next that lasts until node.g + 1 (they are sorted and disjoint).
        const int skip = static_cast<int>(
            std::lower_bound(there.begin(), there.end(), node.g + 1,
                             [](const Interval& i, int t) { return i.last < t; }) -
            there.begin());
        for (int j = skip; j < static_cast<int>(there.size()); ++j) {
          if (node.last != kNever && there[j].first > node.last + 1) break;
          if (!known) {
            move = extra != nullptr ? sipp.beyondBodies(node.s, act, *extra) : sipp.unsafe(node.s, act);
            known = true;
          }
          const int hi = std::min(node.last, there[j].last == kNever ? kNever : there[j].last - 1);
          const int earliest = extra != nullptr ? there[j].first : there[j].first - 1;
          const int departure = Sipp::earliestDeparture(move, std::max(node.g, earliest), hi);
          if (departure >= 0) push(next, next_answers, j, there[j].last, departure + 1, index);
        }
      });
    }
  }
  return result;
}

}  // namespace

int earliestArrivalForGood(const SearchSpace& space, int a, const SoftPathTable& others) {
  MemoryLease lease(space.graph(a).stateIdCount());
  Sipp sipp(space, a, others, 0, lease.memory());
  const PoolRun<Interval> home = sipp.intervals(space.target(a));
  return home.empty() || home.back().last != kNever ? kNever : arrivalFor(home.back(), 0);
}

SafeIntervalResult safeIntervalSearch(const SearchSpace& space, int a, const SoftPathTable& others,
                                      const Deadline& deadline, long long max_expansions,
                                      int max_arrival, double weight) {
  return searchBetween(space, a, others, space.start(a), 0, space.target(a), kNever, 0, deadline,
                       max_expansions, max_arrival, weight);
}

SafeIntervalResult safeIntervalHome(const SearchSpace& space, int a, const SoftPathTable& others,
                                    StateId from, int t0, const Deadline& deadline,
                                    long long max_expansions) {
  return searchBetween(space, a, others, from, t0, space.target(a), kNever, 0, deadline, max_expansions,
                       kNever, 1.0, /*wait_first=*/true);
}

SafeIntervalResult safeIntervalPocket(const SearchSpace& space, int a, const SoftPathTable& others,
                                      StateId from, int t0, StateId pocket, const Deadline& deadline,
                                      long long max_expansions) {
  return searchBetween(space, a, others, from, t0, pocket, t0, 0, deadline, max_expansions, kNever, 1.0,
                       /*wait_first=*/true, /*hold=*/true);
}

SafeIntervalResult safeIntervalSegment(const SearchSpace& space, int a,
                                       const SoftPathTable& others, StateId from, int t0,
                                       StateId to, int t1, int max_delay,
                                       const Deadline& deadline, long long max_expansions) {
  if (t1 == SoftPathTable::kNever) to = space.target(a);
  return searchBetween(space, a, others, from, t0, to, t1, max_delay, deadline, max_expansions);
}

}  // namespace fleet_planner
