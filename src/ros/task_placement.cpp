// Placing a request's tasks on the map; see task_placement.h.
#include "task_placement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "fleet_planner/model/footprint_cells.h"
#include "fleet_planner/model/instance_check.h"
#include "fleet_planner/ros/conversions.h"
#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

namespace {

using RobotResultMsg = fleet_planner::RobotResult;

std::string quoted(const std::string& id) { return "robot '" + id + "'"; }

std::string poseText(const geometry_msgs::Pose2D& p) {
  char buf[128];
  std::snprintf(buf, sizeof(buf), "(%.6g, %.6g, %.6g)", p.x, p.y, p.theta);
  if (std::abs(p.x) < 1e9 && std::abs(p.y) < 1e9 && std::abs(p.theta) < 1e9) {
    std::snprintf(buf, sizeof(buf), "(%.3f, %.3f, %.3f)", p.x, p.y, p.theta);
  }
  return buf;
}

std::string metres(double cells, double resolution) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.6g m", cells * resolution);
  return buf;
}

/// Why a footprint (cells) cannot stand anywhere on the map: its bounding box, origin included (the
/// origin is on a map cell), fits the map at no heading. Empty if it might. Checked before the
/// footprint's cells are computed: that takes time and memory growing with the square of its
/// reach, and a registry entry of 1e6 m would never finish.
std::string footprintSizeProblem(const Footprint& f, const GridMap& map) {
  double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
  if (f.kind == Footprint::Kind::Circle) {
    min_x = min_y = -f.radius;
    max_x = max_y = f.radius;
  }
  for (const auto& p : f.outline()) {
    min_x = std::min(min_x, p.x()), max_x = std::max(max_x, p.x());
    min_y = std::min(min_y, p.y()), max_y = std::max(max_y, p.y());
  }
  const double dx = max_x - min_x, dy = max_y - min_y, w = map.width(), h = map.height();
  if ((dx <= w && dy <= h) || (dy <= w && dx <= h)) return {};
  const double res = map.resolution();
  return "footprint (with its origin) spans " + metres(dx, res) + " x " + metres(dy, res) +
         ": larger than the map (" + metres(w, res) + " x " + metres(h, res) + ")";
}

/// Why a robot with `footprint` cannot stand at `pose`'s cell at `yaw` (grid frame): the first
/// blocked or off-map cell its footprint covers there; empty if it can.
std::string yawPoseProblem(const GridMap& grid, const Footprint& footprint, const GridPose& pose, double yaw) {
  for (const Cell& c : footprintCellsAt(footprint, yaw).cells()) {
    const int x = pose.x + c.x, y = pose.y + c.y;
    if (grid.blocked(x, y)) {
      return "at yaw " + std::to_string(yaw).substr(0, 6) + " rad its footprint covers the blocked cell (" +
             std::to_string(x) + "," + std::to_string(y) + ")";
    }
  }
  return "";
}

/// Places one task; a problem goes into `result`.
void placeTask(const fleet_planner::RobotTask& task, const GridMap& grid,
               const std::map<std::string, fleet_planner::RobotFootprint>& registry, const PlannerConfig& config,
               const StartLookup& lookup, RobotResultMsg& result, TaskState& out) {
  result.robot_id = task.robot_id;
  result.status = RobotResultMsg::OK;
  const std::string who = quoted(task.robot_id);
  auto robotError = [&](std::uint8_t status, const std::string& message) {
    result.status = status;
    result.message = who + ": " + message;
  };
  const auto found = registry.find(task.robot_id);
  if (found == registry.end()) {
    std::string known;
    for (const auto& [id, f] : registry) known += (known.empty() ? "" : ", ") + id;
    robotError(RobotResultMsg::UNKNOWN_ROBOT, "not in the footprint registry (known: " +
                                                  (known.empty() ? std::string("none") : known) + ")");
    return;
  }
  std::unique_ptr<FootprintCells> cells;
  try {
    out.footprint = convert(found->second, grid.resolution());
    out.footprint.sweep_tolerance = config.sweep_tolerance;
    const std::string too_large = footprintSizeProblem(out.footprint, grid);
    if (!too_large.empty()) {
      robotError(RobotResultMsg::INVALID_FOOTPRINT, too_large);
      return;
    }
    cells = std::make_unique<FootprintCells>(out.footprint);
  } catch (const InputError& e) {
    result.status = RobotResultMsg::INVALID_FOOTPRINT;
    result.message = e.what();
    return;
  }
  geometry_msgs::Pose2D start = task.start;
  if (task.start_from_tf) {
    std::string error;
    if (!lookup || !lookup(task.robot_id, start, error)) {
      robotError(RobotResultMsg::NO_TRANSFORM, "start from TF: " + (lookup ? error : "no TF lookup available"));
      return;
    }
  }
  auto place = [&](const geometry_msgs::Pose2D& pose, const char* what, std::uint8_t status, GridPose& placed,
                   std::optional<double>& yaw) {
    const GridPoseFit fit = toGridPose(grid, pose, config.poseTolerance());
    if (!fit.ok()) {
      robotError(status, std::string(what) + " " + fit.error);
      return false;
    }
    yaw = fit.yaw;
    // At a yaw off the grid headings, the footprint at that yaw must be free.
    const std::string problem = fit.yaw ? yawPoseProblem(grid, out.footprint, fit.pose, *fit.yaw)
                                        : poseProblem(grid, *cells, fit.pose);
    if (!problem.empty()) {
      robotError(status, std::string(what) + " " + poseText(pose) + " = grid state " + toString(fit.pose) + ": " +
                             problem);
      return false;
    }
    placed = fit.pose;
    return true;
  };
  if (!place(start, "start", RobotResultMsg::INVALID_START, out.start, out.start_yaw)) return;
  if (!place(task.goal, "goal", RobotResultMsg::INVALID_GOAL, out.goal, out.goal_yaw)) return;
  out.placement = {task.robot_id, found->second, toPose2D(grid, out.start), toPose2D(grid, out.goal), -1};
  if (out.start_yaw) out.placement.start.theta = start.theta;
  if (out.goal_yaw) out.placement.goal.theta = task.goal.theta;
}

}  // namespace

std::vector<TaskState> placeTasks(const fleet_planner::PlanFleet::Request& request, const GridMap& grid,
                                  const std::map<std::string, fleet_planner::RobotFootprint>& registry,
                                  const PlannerConfig& config, const StartLookup& lookup, PlanCall& call) {
  const int n = static_cast<int>(request.tasks.size());
  std::vector<TaskState> tasks(n);
  call.response.robots.resize(n);
  for (int i = 0; i < n; ++i) {
    placeTask(request.tasks[i], grid, registry, config, lookup, call.response.robots[i], tasks[i]);
    if (call.response.robots[i].status == RobotResultMsg::OK) call.placements.push_back(tasks[i].placement);
  }
  return tasks;
}

}  // namespace fleet_planner
