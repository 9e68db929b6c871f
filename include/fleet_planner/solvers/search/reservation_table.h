#pragma once
/// Cells taken by moving obstacles over time, for serial backends. Step t is the move from time
/// t to t + 1; a robot holds the cells it sweeps during each step, and after its path ends the
/// cells of its last footprint for every later step. One sorted list of step intervals per cell,
/// stored flat (CSR) so that a cell without reservations costs one comparison.
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

 private:
  struct Interval {
    int first;
    int last;  // inclusive; kForever for "from first on"
  };
  int width_ = 0;
  int height_ = 0;
  std::vector<std::int32_t> offsets_;  // per cell, into intervals_
  std::vector<Interval> intervals_;
  int last_change_ = -1;
};

}  // namespace fleet_planner
