#pragma once
/// A robot's cells along its path, as every conflict check sees them: its footprint's cells at
/// each grid pose and during each step (footprint_cells.h), and, when it starts or ends at a yaw
/// off the grid headings (Robot::start_yaw, target_yaw), its body there and the turn in place
/// of its first or last step. Such a robot's path repeats its first pose (the step that turns
/// it from its start yaw onto the heading; with Robot::start_turn, after resting at that yaw)
/// or its last pose (the step that turns it to its target yaw).
#include <optional>
#include <string>
#include <vector>

#include "fleet_planner/model/action.h"
#include "fleet_planner/model/footprint_cells.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"

namespace fleet_planner {

class RobotCells {
 public:
  /// `cells` and `path` must outlive this object.
  RobotCells(const Robot& robot, const FootprintCells& cells, const Path& path);
  /// The same robot on another path: the cells at its yaws are copied from `shapes` where
  /// `path` starts and ends on the same headings as the path of `shapes` (computing them takes
  /// trigonometry over the whole footprint), else computed. `path` and the footprint cells of
  /// `shapes` must outlive this object.
  RobotCells(const Robot& robot, const RobotCells& shapes, const Path& path);

  /// Empty when the path has the shape the yaws need; otherwise why not.
  const std::string& shapeProblem() const { return shape_problem_; }
  /// What the robot covers at time t (after its path: at rest), relative to stateAt(path, t).
  const CellSet& bodyAt(int t) const;
  /// What it covers during the step t -> t + 1, relative to stateAt(path, t); null if that step
  /// is no legal motion under `model`.
  const CellSet* sweepAt(int t, const ActionModel& model) const;
  /// No cell of any body or sweep lies farther than this from the robot's cell along either axis:
  /// two robots whose cells are farther apart than the sum of their reaches cannot meet.
  int reach() const { return reach_; }
  /// The action of the step t -> t + 1 (a turn to or from a yaw counts as a rotation).
  std::optional<Action> actionAt(int t, const ActionModel& model) const;

 private:
  RobotCells(const Robot& robot, const FootprintCells& cells, const Path& path, const RobotCells* shapes);

  const FootprintCells& cells_;
  const Path& path_;
  int last_;  ///< the path's last time
  int turn_ = -1;  ///< the step of the turn from the start yaw (-1: none)
  int reach_ = 0;
  std::optional<CellSet> start_body_, start_turn_, end_body_, end_turn_;
  std::string shape_problem_;
};

/// The pose robot `r`'s path must end at for its costs: its target, or with a target yaw, where
/// its path ends (at its target's cell, on the heading it turns from).
inline GridPose planTarget(const Robot& r, const Path& path) {
  return r.target_yaw && !path.empty() ? path.back() : r.target;
}

/// planTarget of every robot of `instance` on `plan` (for planMetrics).
inline std::vector<GridPose> planTargets(const Instance& instance, const Plan& plan) {
  std::vector<GridPose> targets;
  for (std::size_t i = 0; i < instance.robots.size(); ++i) {
    targets.push_back(planTarget(instance.robots[i], i < plan.paths.size() ? plan.paths[i] : Path{}));
  }
  return targets;
}

}  // namespace fleet_planner
