#pragma once
/// CBS constraints of one agent, as the low-level search (space_time_astar.h) reads them.
///
/// - On cells: its footprint must not cover cell c at time t, or the cells it sweeps during
///   step t (from t to t + 1) must not include c. A cell shared by two conflicting agents makes
///   every pair of their poses covering it conflict, so forbidding it to one agent or the other
///   splits soundly, and far more strongly than forbidding single states (the mutually
///   conflicting constraint sets of Li et al. 2019).
/// - On an area from a time on: the footprint must not cover, and no sweep include, a cell of
///   another agent's target footprint at time t or later (during steps t, t + 1, ...).
/// - On the path's cost (the time from which it holds its target for good): above t, or at
///   most t. With the area constraint these are the target-conflict split of Li, Gange, Harabor,
///   Stuckey, Ma, Koenig. "New Techniques for Pairwise Symmetry Breaking in Multi-Agent Path
///   Finding." ICAPS 2020, Section 5 (target symmetry), lifted to footprints.
#include <limits>
#include <unordered_map>
#include <vector>

#include "fleet_planner/model/cell_set.h"
#include "fleet_planner/model/footprint_cells.h"
#include "fleet_planner/model/types.h"

namespace fleet_planner {

class AgentConstraints {
 public:
  static constexpr int kForever = std::numeric_limits<int>::max();

  void forbidCellAt(Cell c, int t) { add({t, c, false}); }
  void forbidCellDuring(Cell c, int t) { add({t, c, true}); }
  /// From time t on, no cell of `area` placed at `origin` may be covered (at t, t + 1, ...) or
  /// swept (during step t, t + 1, ...). `area` must outlive this object.
  void forbidAreaFrom(const CellSet& area, Cell origin, int t);
  /// The path's cost must be greater than t: it may not hold its target for good from t on.
  void requireCostAbove(int t);
  /// The path's cost must be at most t: it holds its target for good from t on.
  void requireCostAtMost(int t);

  /// The footprint at pose p at time t covers a forbidden cell.
  bool poseForbidden(const FootprintCells& cells, const GridPose& p, int t) const;
  /// The sweep of `action` from pose p during step t covers a forbidden cell.
  bool stepForbidden(const FootprintCells& cells, const GridPose& p, Action action, int t) const;
  /// Latest time at which standing at p (or waiting there) is forbidden: -1 if never, kForever
  /// if an area constraint forbids it from some time on.
  int lastBlockedAt(const FootprintCells& cells, const GridPose& p) const;
  /// Smallest cost allowed (0 if unconstrained).
  int minCost() const { return min_cost_; }
  /// Largest cost allowed (kForever if unconstrained).
  int maxCost() const { return max_cost_; }
  /// Latest time any constraint speaks of (a step t counts as t + 1, a cost bound c as c); the
  /// constraints are the same at every later time. -1 if none.
  int maxTime() const { return max_time_; }
  /// Some area is forbidden for good (the static world differs from the map).
  bool hasAreas() const { return !areas_.empty(); }
  /// The time from which every area is forbidden (-1 if there is none).
  int areasFrom() const { return areas_from_; }
  bool empty() const { return all_.empty() && areas_.empty() && min_cost_ == 0 && max_cost_ == kForever; }

 private:
  struct Entry {
    int t;
    Cell c;
    bool during;  // during step t, not at time t
  };
  struct Area {
    const CellSet* cells;
    Cell origin;
    int from;
  };
  void add(const Entry& e);
  bool areaHit(const CellSet& mine, const GridPose& p, int t) const;
  std::unordered_map<int, std::vector<Entry>> by_time_;
  std::vector<Entry> all_;
  std::vector<Area> areas_;
  int min_cost_ = 0;
  int max_cost_ = kForever;
  int max_time_ = -1;
  int areas_from_ = -1;
};

}  // namespace fleet_planner
