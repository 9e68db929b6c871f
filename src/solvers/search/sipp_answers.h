#pragma once
// The answers of a safe interval search (Sipp): the steps during which a state or a move of one
// agent meets the others, and each state's safe intervals, kept in the thread's SearchMemory;
// private to safe_interval_search.cpp.
#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "fleet_planner/solvers/search/search_space.h"
#include "sipp_memory.h"

namespace fleet_planner {
namespace sipp_detail {

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
    if ((action == Action::RotateCcw || action == Action::RotateCw) &&
        space_.turnsBackAlike(a_, p.heading, action)) {
      // The turn back from where this one ends sweeps the same cells: one answer for both (a
      // search that turns at a cell asks both).
      const StateId end = graph_.next(s, action);
      const int back = static_cast<int>(action == Action::RotateCcw ? Action::RotateCw : Action::RotateCcw);
      const int end_index = answersOf(end);
      if (const int known = states_[end_index].unsafe[back]; known >= 0) {
        states_[index].unsafe[act] = known;
        return unsafe_[known];
      }
      const Unsafe answer = fresh(s, action, p, index, act);
      states_[end_index].unsafe[back] = states_[index].unsafe[act];
      return answer;
    }
    return fresh(s, action, p, index, act);
  }

  // unsafe()'s answer computed from the table and the reservations, kept as the answer of
  // states_[index] for action `act`.
  Unsafe fresh(StateId s, Action action, const GridPose& p, int index, int act) {
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

}  // namespace sipp_detail
}  // namespace fleet_planner
