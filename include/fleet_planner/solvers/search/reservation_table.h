#pragma once
/// Cells taken by moving obstacles over time, for serial backends. Step t is the move from time
/// t to t + 1; a robot holds the cells it sweeps during each step, and after its path ends the
/// cells of its last footprint for every later step. One sorted list of step intervals per cell,
/// stored flat (CSR) so that a cell without reservations costs one comparison. The same lists per
/// block of kBlock x kBlock cells (the union of its cells' intervals) answer "is any cell of this
/// set taken?" exactly for the many queries of a large footprint far from every moving obstacle:
/// cells are looked at only when a block the set touches is taken at that step.
#include <cstdint>
#include <limits>
#include <vector>

#include "fleet_planner/model/cell_set.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

class ReservationTable {
 public:
  static constexpr int kForever = std::numeric_limits<int>::max();

  ReservationTable() = default;
  ReservationTable(int width, int height, const std::vector<MovingObstacle>& moving, const FleetGraphs& graphs,
                   const ActionModel& model);

  bool empty() const { return intervals_.empty(); }
  /// Cell (x, y) is taken during step t.
  bool taken(int x, int y, int t) const;
  /// Some cell of `set` placed at `origin` is taken during step t.
  bool taken(const CellSet& set, Cell origin, int t) const;
  /// Last step during which some cell of the set is taken (kForever if held forever, -1 if never).
  int lastTaken(const CellSet& set, Cell origin) const;
  /// Every (first, last) step interval during which some cell of the set is taken, appended to
  /// `out` unsorted and possibly overlapping (last is kForever for "from first on").
  void takenIntervals(const CellSet& set, Cell origin, std::vector<std::pair<int, int>>& out) const;
  /// Last finite step of any reservation; after it the table never changes (-1 if empty).
  int lastChange() const { return last_change_; }
  /// The largest pitch of contact probes (contact_probe.h) that find every reservation: the side
  /// of the largest square every reserved set holds, or 1 unless every one is 4-connected
  /// (kForever when the table is empty). The queries above may be asked with such a probe of a
  /// set instead of the set: the answers are the same.
  int contactPitch() const { return pitch_; }

 private:
  static constexpr int kBlock = 8;
  struct Interval {
    int first;
    int last;  // inclusive; kForever for "from first on"
  };
  struct Entry {
    std::int32_t key;  // a cell or a block
    Interval interval;
  };
  /// Sorts and merges `entries` into per-key sorted disjoint interval lists (CSR over `keys`).
  static void buildLists(std::vector<Entry>& entries, std::size_t keys, std::vector<std::int32_t>& offsets,
                         std::vector<Interval>& intervals);
  /// Some interval of the list [begin, end) contains t.
  static bool contains(const Interval* begin, const Interval* end, int t);
  bool cellsTaken(const CellSet& set, Cell origin, int t) const;

  int width_ = 0;
  int height_ = 0;
  int blocks_x_ = 0;
  int blocks_y_ = 0;
  std::vector<std::int32_t> offsets_;  // per cell, into intervals_
  std::vector<Interval> intervals_;
  std::vector<std::int32_t> block_offsets_;  // per block, into block_intervals_
  std::vector<Interval> block_intervals_;
  int last_change_ = -1;
  int pitch_ = kForever;
};

}  // namespace fleet_planner
