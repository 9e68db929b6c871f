#include "fleet_planner/solvers/search/safe_interval_search.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <memory>

#include "sipp_memory.h"

namespace fleet_planner {

thread_local std::unique_ptr<sipp_detail::SearchMemory> sipp_detail::MemoryLease::idle_;

namespace {

using namespace sipp_detail;

class Sipp {
 public:
  // A search from step `from` on: the steps before it are left out of every answer (counted
  // safe), so that the passes of the others before it cost nothing. Its answers are kept in
  // `memory` (cleared).
  Sipp(const SearchSpace& space, int a, const SoftPathTable& others, int from, SearchMemory& memory)
      : space_(space), a_(a), others_(others), graph_(space.graph(a)), from_(from),
        state_index_(memory.state_index), states_(memory.states), unsafe_(memory.unsafe),
        run_pool_(memory.run_pool), interval_pool_(memory.interval_pool), merged_(memory.merged),
        interval_scratch_(memory.interval_scratch), runs_(memory.runs), best_of_(memory.best_of) {}

  // The index of s's answers in states_, added (none asked yet) if s has none.
  int answersOf(StateId s) {
    int& index = state_index_[s];
    if (index < 0) {
      index = static_cast<int>(states_.size());
      StateAnswers answers{s, {}, {}, -1};
      answers.unsafe.fill(-1);
      states_.push_back(answers);
    }
    return index;
  }
  const StateAnswers& answers(int index) const { return states_[index]; }

  // Steps from from_ on during which doing `action` from s collides with another agent or a
  // moving obstacle.
  Unsafe unsafe(StateId s, Action action) {
    const int index = answersOf(s), act = static_cast<int>(action);
    if (const int known = states_[index].unsafe[act]; known >= 0) return unsafe_[known];
    const GridPose p = graph_.pose(s);
    if (action == Action::Wait) {  // a disc waits alike at every heading: one answer
      const int same = space_.sameWaitHeading(a_, p.heading);
      if (same != p.heading) {
        const StateId alike = graph_.id({p.x, p.y, same});
        const Unsafe answer = unsafe(alike, Action::Wait);
        // Kept under this state too: the next ask is one lookup.
        states_[index].unsafe[act] = states_[state_index_[alike]].unsafe[act];
        return answer;
      }
    }
    int forever = kNever, lo = kNever, hi = -1;
    if (others_.lastMove() < kSteps) {
      runs_.clear();
      others_.markUnsafe(a_, s, action, steps_.data(), lo, hi, forever, from_);
    } else {
      others_.unsafeRuns(a_, s, action, runs_, forever, from_);
    }
    if (forever != kNever) runs_.emplace_back(forever, kNever);
    addReservations(space_.probe(a_, p.heading, action), {p.x, p.y});
    return store(index, act, lo, hi);
  }

  // Steps from from_ on during which the cells of the move `action` from s outside its two
  // bodies (SearchSpace::moveExtra, which must decompose it) meet another agent or a moving
  // obstacle. The move collides during step t iff the body before, the body after or these
  // cells do; a search departs only within a safe interval of the state it leaves and arrives
  // within one of the state it enters, so it reads these alone (see searchBetween).
  Unsafe beyondBodies(StateId s, Action action, const CellSet& extra) {
    const int index = answersOf(s), act = static_cast<int>(action);
    if (const int known = states_[index].unsafe[act]; known >= 0) return unsafe_[known];
    const GridPose p = graph_.pose(s);
    runs_.clear();
    int forever = kNever;
    others_.spansAt(a_, extra, {p.x, p.y}, runs_, forever, from_);
    if (forever != kNever) runs_.emplace_back(forever, kNever);
    addReservations(extra, {p.x, p.y});
    return store(index, act, kNever, -1);
  }

  // Appends to runs_ the steps from from_ on during which a moving obstacle covers a cell of
  // `cells` placed at `origin`.
  void addReservations(const CellSet& cells, Cell origin) {
    const ReservationTable& reservations = space_.reservations();
    if (reservations.empty()) return;
    const std::size_t from = runs_.size();
    reservations.takenIntervals(cells, origin, runs_);
    std::size_t kept = from;
    for (std::size_t i = from; i < runs_.size(); ++i) {
      if (runs_[i].second == ReservationTable::kForever) runs_[i].second = kNever;
      if (runs_[i].second < from_) continue;
      runs_[kept++] = {std::max(runs_[i].first, from_), runs_[i].second};
    }
    runs_.resize(kept);
  }

  // The union of runs_ and of the bitset's steps lo..hi, kept as the answer of states_[index]
  // for action `act`.
  Unsafe store(int index, int act, int lo, int hi) {
    unionOf(runs_, merged_, lo, hi);
    states_[index].unsafe[act] = static_cast<int>(unsafe_.size());
    unsafe_.push_back(run_pool_.add(merged_));
    return unsafe_.back();
  }

  // The index of s's answers in states_, its safe intervals among them (with one entry each in
  // best_of_, -1).
  int intervalsOf(StateId s) {
    const int index = answersOf(s);
    if (states_[index].best >= 0) return index;
    const Unsafe u = unsafe(s, Action::Wait);
    std::vector<Interval>& out = interval_scratch_;
    out.clear();
    int first = 0;
    bool closed = false;
    for (const auto& [from, to] : u) {
      if (from > first) out.push_back({first, from - 1});
      if (to == kNever) {
        closed = true;
        break;
      }
      first = to + 1;
    }
    if (!closed) out.push_back({first, kNever});
    StateAnswers& answers = states_[index];
    answers.intervals = interval_pool_.add(out);
    answers.best = static_cast<int>(best_of_.size());
    best_of_.resize(best_of_.size() + out.size(), -1);
    return index;
  }
  PoolRun<Interval> intervals(StateId s) { return states_[intervalsOf(s)].intervals; }
  // The node of (states_[index]'s state, its interval j): -1 if none.
  int& bestNode(int index, int j) { return best_of_[states_[index].best + j]; }
  // Forgets every state's node.
  void forgetNodes() { std::fill(best_of_.begin(), best_of_.end(), -1); }

  // The union of `runs` (inclusive; second == kNever: from first on) as sorted, disjoint,
  // non-adjacent runs. A motion's runs number about a hundred, most of them repeats from
  // neighbouring cells: when they all end within the first kSteps steps their steps are set in
  // a bitset and read back in order, else they are sorted and merged.
  // Steps lo..hi of the bitset may be set already (markUnsafe): they join the union.
  void unionOf(std::vector<std::pair<int, int>>& runs, std::vector<std::pair<int, int>>& out, int lo, int hi) {
    out.clear();
    int forever = kNever;
    if (hi >= 0) {
      bool beyond = false;
      for (const auto& r : runs) beyond = beyond || (r.second != kNever && r.second >= kSteps);
      if (beyond) {  // the sort below: the marked steps become runs first
        bitsToRuns(lo, hi, runs);
        lo = kNever;
        hi = -1;
      }
    }
    for (const auto& [first, last] : runs) {
      if (last == kNever) {
        forever = std::min(forever, first);
      } else {
        lo = std::min(lo, first);
        hi = std::max(hi, last);
      }
    }
    if (hi >= kSteps) {
      std::sort(runs.begin(), runs.end());
      for (const auto& r : runs) {
        if (!out.empty() && (out.back().second == kNever || r.first <= out.back().second + 1)) {
          if (out.back().second != kNever) out.back().second = std::max(out.back().second, r.second);
        } else {
          out.push_back(r);
        }
      }
      return;
    }
    if (hi >= 0) {
      for (const auto& [first, last] : runs) {
        if (last != kNever) SoftPathTable::markSteps(steps_.data(), first, last);
      }
      bitsToRuns(lo, hi, out);
    }
    if (forever == kNever) return;
    // The runs from `forever` on are covered; one that reaches it joins the last run.
    while (!out.empty() && out.back().first >= forever) out.pop_back();
    if (!out.empty() && out.back().second + 1 >= forever) {
      out.back().second = kNever;
    } else {
      out.emplace_back(forever, kNever);
    }
  }

  // Appends the runs of set steps in lo..hi of the bitset, in order, and clears it.
  void bitsToRuns(int lo, int hi, std::vector<std::pair<int, int>>& out) {
    // The first set (or clear) step at or after `from`; past hi's word if none.
    auto scan = [&](int from, bool set) {
      for (int word = from >> 6; word <= (hi >> 6); ++word) {
        std::uint64_t bits = set ? steps_[word] : ~steps_[word];
        if (word == (from >> 6)) bits &= ~0ULL << (from & 63);
        if (bits != 0) return (word << 6) + __builtin_ctzll(bits);
      }
      return ((hi >> 6) + 1) << 6;
    };
    int t = lo;
    while (t <= hi) {
      const int first = scan(t, true);
      if (first > hi) break;
      const int last = scan(first, false) - 1;
      out.emplace_back(first, last);
      t = last + 1;
    }
    std::fill(steps_.begin() + (lo >> 6), steps_.begin() + (hi >> 6) + 1, 0ULL);
  }

  // Earliest departure step in [lo, hi] at which `u` allows the move (-1 if none).
  static int earliestDeparture(const Unsafe& u, int lo, int hi) {
    // The first run that ends at or after lo: if it has started by lo, leave right after it.
    auto it = std::lower_bound(u.begin(), u.end(), lo,
                               [](const std::pair<int, int>& r, int t) { return r.second < t; });
    int t = lo;
    if (it != u.end() && it->first <= lo) {
      if (it->second == kNever) return -1;
      t = it->second + 1;
    }
    return t <= hi ? t : -1;
  }

 private:
  const SearchSpace& space_;
  int a_;
  const SoftPathTable& others_;
  const StateGraph& graph_;
  const int from_;
  // The answers so far (SearchMemory).
  std::vector<int>& state_index_;
  std::vector<StateAnswers>& states_;
  std::vector<Unsafe>& unsafe_;
  StablePool<std::pair<int, int>>& run_pool_;
  StablePool<Interval>& interval_pool_;
  std::vector<std::pair<int, int>>& merged_;    // scratch
  std::vector<Interval>& interval_scratch_;     // scratch
  std::vector<std::pair<int, int>>& runs_;      // scratch
  std::vector<int>& best_of_;  // (state, interval) -> node of searchBetween (StateAnswers::best)
  static constexpr int kSteps = 4096;          // steps of the bitset of unionOf
  std::array<std::uint64_t, kSteps / 64> steps_{};  // unionOf's bitset, all clear between calls
};

}  // namespace

namespace {

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
