#pragma once
/// The cells a plan's robots occupy while it is executed, step by step, as the validator sees
/// them (robot_cells.h): robot i at rest at state k covers bodyAt(k); doing step t (the motion
/// from state t to t + 1) it covers sweepAt(t), which holds both end bodies; after its last
/// state it rests there. Both placed at stateAt(path, t). Shared by the dependency builder and
/// the execution simulation, so that both reason about exactly the cells the validator checked.
#include <memory>
#include <vector>

#include "fleet_planner/model/action.h"
#include "fleet_planner/model/cell_set.h"
#include "fleet_planner/model/footprint_cells.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"
#include "fleet_planner/model/robot_cells.h"

namespace fleet_planner {

/// A set of cells placed on the map: `cells` relative to `at`.
struct PlacedCells {
  const CellSet* cells = nullptr;
  Cell at;
};

/// True when the two placed sets share a cell (bounding boxes first).
bool overlap(const PlacedCells& a, const PlacedCells& b);

class PlanCells {
 public:
  /// `instance` and `plan` must outlive this object. Throws InvalidInput when the plan does not
  /// have one non-empty path per robot, or a path has a step that is no legal motion under
  /// `model` or not the shape its start or target yaw needs (what validatePlan reports as such).
  /// Steps before `from` (every robot has done them, during an execution) are not looked at:
  /// during() and isMove() must not be asked about them.
  PlanCells(const Instance& instance, const Plan& plan, const ActionModel& model = {}, int from = 0);
  /// The first step looked at.
  int from() const { return from_; }

  int robots() const { return static_cast<int>(paths_.size()); }
  const Path& path(int robot) const { return *paths_[robot]; }
  /// The index of the robot's last state: path size - 1 (its number of steps).
  int lastState(int robot) const { return static_cast<int>(paths_[robot]->size()) - 1; }
  /// Step t is a move (anything but a wait: a turn to or from a yaw counts as a move).
  bool isMove(int robot, int t) const { return moves_[robot][t]; }
  /// What the robot covers at rest at state k (k past the last state: at its last state).
  PlacedCells atRest(int robot, int k) const;
  /// What it covers during step t (t at or past the last state: at rest there).
  PlacedCells during(int robot, int t) const;

 private:
  std::vector<const Path*> paths_;
  std::vector<std::shared_ptr<const FootprintCells>> footprints_;
  std::vector<std::unique_ptr<RobotCells>> cells_;
  std::vector<std::vector<const CellSet*>> sweeps_;  ///< [robot][t], t < lastState
  std::vector<std::vector<bool>> moves_;             ///< [robot][t], t < lastState
  int from_ = 0;
};

}  // namespace fleet_planner
