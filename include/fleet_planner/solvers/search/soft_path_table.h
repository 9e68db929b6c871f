#pragma once
/// The current paths of a subproblem's agents as soft obstacles (LA-LNS, la_lns.h): which
/// agents a candidate motion would collide with, found through the steps each cell is swept
/// (read at the cells of the motion's contact probe, SearchSpace::probe): a query costs the
/// agents that pass nearby, not the fleet.
///
/// Step t is the motion from time t to t + 1; an agent sweeps the cells of its action during a
/// step (its footprint when it waits) and, once its path has ended, stands at its last state
/// for every later step. Two agents collide during step t when their sweeps share a cell: that
/// covers the vertex conflicts at t and t + 1 and the transfer conflicts of the step, the model
/// of agent_conflicts.h and of the validator.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "fleet_planner/solvers/search/agent_conflicts.h"
#include "fleet_planner/solvers/search/search_space.h"

namespace fleet_planner {

class SoftPathTable {
 public:
  /// An empty table; its per-cell index is allocated at the first insert, so that an empty
  /// table (a search around moving obstacles only) costs nothing on a large map.
  explicit SoftPathTable(const SearchSpace& space);

  /// Puts agent a's path in the table (replacing none: a must not be in it). Not empty.
  void insert(int a, const StatePath& path);
  /// Takes agent a's path out (a must be in it).
  void remove(int a);
  bool contains(int a) const { return !paths_[a].empty(); }
  const StatePath& path(int a) const { return paths_[a]; }

  /// Agents in the table other than a that collide with a doing `action` from s during step t,
  /// each once, appended to `out`.
  void collisions(int a, StateId s, Action action, int t, std::vector<int>& out) const;
  /// Agents in the table other than a that stand for good where their paths end and meet a
  /// doing `action` from s, each once, appended to `out`: collisions() at step lastMove() + 1,
  /// answered from the cells where robots stand for good (most of a map has none).
  void collisionsAtEnd(int a, StateId s, Action action, std::vector<int>& out) const;
  /// The same for the cells of `cells` placed at `origin` (any cells: not a probe).
  void collisionsAtEnd(int a, const CellSet& cells, Cell origin, std::vector<int>& out) const;
  /// Agents in the table other than a that collide with a standing at s during some step t or
  /// later, each once, appended to `out`.
  void collisionsHolding(int a, StateId s, int t, std::vector<int>& out) const;
  /// Agents in the table that collide with agent a's path in the table (or with `path`, when
  /// given, as if it were a's), sorted.
  std::vector<int> partners(int a) const { return partners(a, paths_[a]); }
  std::vector<int> partners(int a, const StatePath& path) const;
  /// The steps during which agent a doing `action` from s would collide with an agent in the
  /// table (other than a), as (first, last) runs, unsorted and possibly overlapping, up to
  /// lastMove(); and the first step from which it collides for good with an agent standing at
  /// its end (kNever if none). Steps before `from` are left out (runs start at `from` or later):
  /// a search from step `from` on never asks about them.
  static constexpr int kNever = 1 << 30;
  void unsafeRuns(int a, StateId s, Action action, std::vector<std::pair<int, int>>& runs,
                  int& forever_from, int from = 0) const;
  /// unsafeRuns as a set of steps: sets bit t % 64 of steps[t / 64] for every step t of those
  /// runs, widening [lo, hi] to them, and lowers forever_from as unsafeRuns does. `steps` must
  /// hold lastMove() + 1 bits.
  void markUnsafe(int a, StateId s, Action action, std::uint64_t* steps, int& lo, int& hi,
                  int& forever_from, int from = 0) const;
  /// The steps during which an agent in the table other than a sweeps a cell of `cells` placed
  /// at `origin`, as raw runs appended to `runs` (one per span met, first raised to `from`;
  /// spans ending before `from` left out), and lowers forever_from as unsafeRuns does. For a
  /// few cells read one by one (SearchSpace::moveExtra), not a probe.
  void spansAt(int a, const CellSet& cells, Cell origin, std::vector<std::pair<int, int>>& runs,
               int& forever_from, int from = 0) const;
  /// Sets the bits of steps first..last (bit t % 64 of steps[t / 64]).
  static void markSteps(std::uint64_t* steps, int first, int last) {
    if ((first >> 6) == (last >> 6)) {  // most runs: a few steps within one word
      const int n = last - first + 1;
      steps[first >> 6] |= (n == 64 ? ~std::uint64_t{0} : ((std::uint64_t{1} << n) - 1) << (first & 63));
      return;
    }
    for (int t = first; t <= last;) {  // whole words at once where the run covers them
      const int word = t >> 6, bit = t & 63;
      const int n = std::min(64 - bit, last - t + 1);
      steps[word] |= (n == 64 ? ~std::uint64_t{0} : ((std::uint64_t{1} << n) - 1) << bit);
      t += n;
    }
  }
  /// Last step during which some agent in the table moves (every path of length 1: -1).
  int lastMove() const { return last_move_; }

 private:
  // Adds (on = true) or removes the entries of a's path.
  void index(int a, bool on);
  struct Span;
  // Calls f(agent, first, last) for every span of another agent than a, at `cells` placed at
  // `origin`, that ends at `from` or later (first raised to `from`); lowers forever_from to the
  // first step of those that do not end.
  template <class F>
  void forOtherSpans(int a, const CellSet& cells, Cell origin, int from, int& forever_from, F&& f) const;
  // The same at the cells of the probe of a doing `action` from s.
  template <class F>
  void forOtherSpans(int a, StateId s, Action action, int from, int& forever_from, F&& f) const {
    const GridPose p = space_.graph(a).pose(s);
    forOtherSpans(a, space_.probe(a, p.heading, action), {p.x, p.y}, from, forever_from, f);
  }
  // Starts a query: a new query_ stamp (all stamps cleared when the counter wraps).
  void newQuery() const;
  // True the first time agent b is met in the current query (query_).
  bool firstVisit(int b) const;

  const SearchSpace& space_;
  int width_, height_;
  std::vector<StatePath> paths_;
  int last_move_ = -1;
  // Per map cell, the steps during which an agent sweeps it (waits and moves alike), one span
  // per stretch of consecutive steps; last == kNever: the agent stands there at its end. The
  // queries read these: the cells of a motion, not every motion nearby.
  struct Span {
    int first, last;
    int agent;
  };
  std::vector<std::vector<Span>> cell_spans_;
  // Per map cell, the blocks of kBlockSteps steps that some span of it touches (bit b: steps
  // b * kBlockSteps to b * kBlockSteps + kBlockSteps - 1; the last bit: that block and every
  // later step). A step query (collisions) skips a cell whose bit is clear without reading its
  // spans: most cells of a probe are swept at other times.
  static constexpr int kBlockSteps = 16;
  static std::uint64_t blocksOf(int first, int last);
  static std::uint64_t blockOf(int t);
  std::vector<std::uint64_t> cell_blocks_;
  // Per map cell and per square of kEndSide x kEndSide cells, how many agents stand there for
  // good (spans with last == kNever): collisionsAtEnd() skips a motion whose squares have none.
  static constexpr int kEndSide = 8;
  int end_squares_x_ = 0;
  std::vector<std::uint16_t> end_cells_, end_squares_;
  // Per map cell, the sum of the agents standing there for good: the agent itself when
  // end_cells_ counts one (the usual case), so that its spans need not be read.
  std::vector<int> end_agents_;
  void countEnd(int cell, int agent, int delta);
  // The steps during which a cell is swept by spans that end, as a bitset (bit t % 64 of word
  // t / 64; first..last: the steps they cover, none if last < 0) whose nonzero words are the
  // bits of `used`, and the first step from which someone stands there for good (kNever: none);
  // rebuilt from the spans when asked after they changed (stale). Kept only for the cells
  // markUnsafe has read (horizons of at most 64 words), one record each in step_records_: a
  // head of kHeadWords words, then step_stride_ words of bits, so that a cell's answer is one
  // read of adjacent memory (markUnsafe reads a probe's cells in turn, each a cache miss).
  static constexpr int kHeadWords = 3;  // used; first and last; forever and stale
  // The record of `cell`, brought up to date.
  const std::uint64_t* stepsOf(int cell) const;
  // Marks the record of `cell`, if any, stale.
  void staleSteps(int cell) {
    if (step_slot_[cell] >= 0) step_records_[recordAt(step_slot_[cell]) + 2] |= std::uint64_t{1} << 32;
  }
  std::size_t recordAt(int slot) const {
    return static_cast<std::size_t>(slot) * static_cast<std::size_t>(kHeadWords + step_stride_);
  }
  // Per map cell, its record's index, or kNoSlot (none yet) or kNoSpans (nobody sweeps it, and
  // no record): markUnsafe's one read of a cell before its record.
  static constexpr int kNoSlot = -1, kNoSpans = -2;
  mutable std::vector<int> step_slot_;
  mutable std::vector<std::uint64_t> step_records_;
  mutable int step_slots_ = 0, step_stride_ = 0;
  mutable std::vector<std::vector<std::pair<int, int>>> agent_runs_;  // unsafeRuns' scratch
  mutable std::vector<int> met_;                                     // its agents
  mutable std::vector<std::uint32_t> stamp_;       // dedup of query results, per agent
  mutable std::vector<std::uint32_t> cell_stamp_;  // and per cell (removal)
  mutable std::uint32_t query_ = 0;
};

}  // namespace fleet_planner
