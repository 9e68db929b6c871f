// A robot's cells along its path; see robot_cells.h.
#include "fleet_planner/model/robot_cells.h"

#include <algorithm>

namespace fleet_planner {

namespace {

int farthest(const CellSet& c) { return c.empty() ? 0 : std::max({-c.minX(), c.maxX(), -c.minY(), c.maxY()}); }

}  // namespace

RobotCells::RobotCells(const Robot& robot, const FootprintCells& cells, const Path& path)
    : RobotCells(robot, cells, path, nullptr) {}

RobotCells::RobotCells(const Robot& robot, const RobotCells& shapes, const Path& path)
    : RobotCells(robot, shapes.cells_, path, &shapes) {}

RobotCells::RobotCells(const Robot& robot, const FootprintCells& cells, const Path& path, const RobotCells* shapes)
    : cells_(cells), path_(path), last_(static_cast<int>(path.size()) - 1) {
  // The farthest cell along an axis of any body or sweep on the grid headings (a body lies in
  // its rotations' sweeps, a shorter move's sweep in the step's); the yaw shapes' below.
  for (int h = 0; h < kHeadings; ++h) {
    for (int a = 0; a < kActions; ++a) reach_ = std::max(reach_, farthest(cells.swept(h, static_cast<Action>(a))));
  }
  turn_ = robot.start_yaw ? std::max(0, robot.start_turn) : -1;
  const int turns = (robot.start_yaw ? turn_ + 1 : 0) + (robot.target_yaw ? 1 : 0);
  if (path.empty()) return;
  if (last_ < turns) {
    shape_problem_ = "a path that turns from a start yaw or to a target yaw needs a step for each turn";
    return;
  }
  // The yaw shapes depend on the footprint, the yaws and the path's first and last headings:
  // taken from `shapes` when those agree (the same robot on another path).
  const bool same_start = shapes && shapes->start_turn_ && !shapes->path_.empty() &&
                          shapes->path_.front().heading == path.front().heading;
  const bool same_end = shapes && shapes->end_turn_ && !shapes->path_.empty() &&
                        shapes->path_.back().heading == path.back().heading;
  if (robot.start_yaw) {
    for (int t = 1; t <= turn_ + 1; ++t) {
      if (path[t] != path[0]) {
        shape_problem_ = "the path must rest at its start yaw and turn in place onto " + toString(path[0]) +
                         " by step " + std::to_string(turn_);
      }
    }
    start_body_ = same_start ? shapes->start_body_ : footprintCellsAt(cells.footprint(), *robot.start_yaw);
    start_turn_ = same_start ? shapes->start_turn_
                             : turnSweep(cells.footprint(), *robot.start_yaw, headingYaw(path[0].heading));
  }
  if (robot.target_yaw) {
    if (path[last_ - 1] != path[last_]) shape_problem_ = "the last step must turn in place from " + toString(path[last_]) + " to the target yaw";
    end_body_ = same_end ? shapes->end_body_ : footprintCellsAt(cells.footprint(), *robot.target_yaw);
    end_turn_ = same_end ? shapes->end_turn_
                         : turnSweep(cells.footprint(), headingYaw(path[last_].heading), *robot.target_yaw);
  }
  for (const std::optional<CellSet>* c : {&start_body_, &start_turn_, &end_body_, &end_turn_}) {
    if (*c) reach_ = std::max(reach_, farthest(**c));
  }
}

const CellSet& RobotCells::bodyAt(int t) const {
  if (t <= turn_ && start_body_) return *start_body_;
  if (t >= last_ && end_body_) return *end_body_;
  return cells_.body(stateAt(path_, t).heading);
}

std::optional<Action> RobotCells::actionAt(int t, const ActionModel& model) const {
  if ((t == turn_ && start_turn_) || (t == last_ - 1 && end_turn_)) return Action::RotateCcw;
  if (t < turn_ && start_body_) return Action::Wait;
  return actionBetween(stateAt(path_, t), stateAt(path_, t + 1), model);
}

const CellSet* RobotCells::sweepAt(int t, const ActionModel& model) const {
  if (t == turn_ && start_turn_) return &*start_turn_;
  if (t < turn_ && start_body_) return &*start_body_;
  if (t == last_ - 1 && end_turn_) return &*end_turn_;
  if (t >= last_) return &bodyAt(t);
  const GridPose &from = stateAt(path_, t), &to = stateAt(path_, t + 1);
  const auto action = actionBetween(from, to, model);
  if (!action) return nullptr;
  if (*action == Action::Forward || *action == Action::Backward) {
    return &cells_.moveSwept(from.heading, *action == Action::Forward, moveLength(from, to));
  }
  return &cells_.swept(from.heading, *action);
}

}  // namespace fleet_planner
