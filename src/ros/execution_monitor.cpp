#include "fleet_planner/ros/execution_monitor.h"

#include <algorithm>
#include <cmath>

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <diagnostic_msgs/KeyValue.h>
#include <fleet_planner/RobotExecution.h>

#include "fleet_planner/execution/step_dependencies.h"
#include "fleet_planner/model/footprint_cells.h"
#include "fleet_planner/ros/conversions.h"
#include "fleet_planner/ros/path_messages.h"

namespace fleet_planner {

namespace {

using RobotExecutionMsg = fleet_planner::RobotExecution;

// A map-frame pose in the grid's frame: cells (continuous) and the yaw.
struct GridPoint {
  double x, y, yaw;
};

GridPoint toGrid(const GridMap& map, const geometry_msgs::Pose2D& pose) {
  const MapOrigin& o = map.origin();
  const double c = std::cos(o.yaw), s = std::sin(o.yaw);
  const double dx = pose.x - o.x, dy = pose.y - o.y;
  return {(c * dx + s * dy) / map.resolution(), (-s * dx + c * dy) / map.resolution(), pose.theta - o.yaw};
}

}  // namespace

void ExecutionMonitor::start(ExecutablePlan plan, double seconds_per_step, const std::string& map_frame,
                             const ros::Time& now) {
  ActionModel model;
  model.step = plan.lattice_step;
  model.allow_backward = plan.allow_backward;
  StepDependencies dependencies = buildStepDependencies(plan.instance, plan.plan, model);
  const std::size_t count = dependencies.count();
  tracker_ = std::make_unique<ExecutionTracker>(plan.plan, std::move(dependencies));
  plan_ = std::move(plan);
  matchers_.clear();
  for (const auto& poses : plan_.poses) {
    matchers_.emplace_back(poses, settings_.position_tolerance, settings_.heading_tolerance);
  }
  ids_.clear();
  for (const Robot& r : plan_.instance.robots) ids_.push_back(r.id);
  message_ = fleet_planner::FleetExecution();
  message_.header.frame_id = map_frame;
  message_.header.stamp = now;
  message_.plan = ++plans_;
  message_.seconds_per_step = seconds_per_step;
  message_.dependencies = static_cast<std::uint32_t>(count);
  message_.robots.resize(ids_.size());
  for (std::size_t i = 0; i < ids_.size(); ++i) {
    message_.robots[i].robot_id = ids_[i];
    message_.robots[i].last_state = tracker_->lastState(static_cast<int>(i));
  }
  waiting_since_.assign(ids_.size(), ros::Time());
  touching_.clear();
  poses_.clear();
  cells_.reset();
  seconds_per_step_ = seconds_per_step;
}

std::vector<int> ExecutionMonitor::robotsIn(std::uint8_t state) const {
  std::vector<int> out;
  for (std::size_t i = 0; i < message_.robots.size(); ++i) {
    if (message_.robots[i].state == state) out.push_back(static_cast<int>(i));
  }
  return out;
}

std::vector<int> ExecutionMonitor::blockedRobots() const { return robotsIn(RobotExecutionMsg::BLOCKED); }

std::vector<int> ExecutionMonitor::offPathRobots() const { return robotsIn(RobotExecutionMsg::OFF_PATH); }

ReplanReport ExecutionMonitor::replan(const std::vector<int>& robots, double time_limit, const PoseTolerance& tolerance) {
  ReplanRequest rq;
  std::string names;
  for (int a : robots) {
    const bool off_path = message_.robots[a].state == RobotExecutionMsg::OFF_PATH && a < static_cast<int>(poses_.size()) && poses_[a];
    if (off_path) {
      // From where it stands: a pose no state of its plan has, snapped to the nearest cell
      // centre however far (at most half a cell's diagonal) it is from it.
      PoseTolerance snap = tolerance;
      snap.position = std::max(snap.position, 0.71 * plan_.map->resolution());
      const GridPoseFit fit = toGridPose(*plan_.map, *poses_[a], snap);
      if (!fit.ok()) {
        ReplanReport report;
        report.status = SolveStatus::InvalidInput;
        report.message = "'" + ids_[a] + "' (off its path) stands at a pose that is not on the map: " + fit.error;
        ++message_.replans_refused;  // refused like any re-plan that finds no way
        message_.last_replan = report.message;
        return report;
      }
      rq.moved.push_back({a, fit.pose, fit.yaw});
      names += (names.empty() ? "'" : ", '") + ids_[a] + "' (off its path)";
      continue;
    }
    if (tracker_->done(a)) continue;
    rq.robots.push_back(a);
    names += (names.empty() ? "'" : ", '") + ids_[a] + "'";
    // Around the robot it waits for: that robot's steps up to the state it waits for.
    if (const auto holder = tracker_->blockedBy(a); holder && tracker_->releasedUpTo(a) == tracker_->progress(a)) {
      rq.avoid.push_back({holder->robot, holder->state});
    }
  }
  if (rq.robots.empty() && rq.moved.empty()) {
    ReplanReport report;
    report.nothing_to_do = true;
    report.message = "every robot asked for has arrived";
    return report;
  }
  return replanWith(std::move(rq), "re-planning " + names, time_limit);
}

ReplanReport ExecutionMonitor::assignGoals(const std::vector<std::pair<int, geometry_msgs::Pose2D>>& goals,
                                           double time_limit, const PoseTolerance& tolerance) {
  ReplanRequest rq;
  std::string names;
  for (const auto& [a, goal] : goals) {
    const GridPoseFit fit = toGridPose(*plan_.map, goal, tolerance);
    if (!fit.ok()) {
      ReplanReport report;
      report.invalid_goal = true;
      report.message = "'" + ids_[a] + "': goal " + fit.error;
      return report;
    }
    rq.targets.push_back({a, fit.pose, fit.yaw});
    names += (names.empty() ? "'" : ", '") + ids_[a] + "'";
  }
  ReplanReport report = replanWith(std::move(rq), "new goals for " + names, time_limit);
  report.invalid_goal = report.status == SolveStatus::InvalidInput;
  return report;
}

ReplanReport ExecutionMonitor::replanWith(ReplanRequest rq, const std::string& names, double time_limit) {
  ReplanReport report;
  const int n = static_cast<int>(ids_.size());
  rq.map = plan_.map.get();
  rq.instance = &plan_.instance;
  rq.graphs = plan_.graphs.get();
  rq.plan = &plan_.plan;
  for (int i = 0; i < n; ++i) {
    rq.progress.push_back(tracker_->progress(i));
    rq.released.push_back(std::max<int>(rq.progress.back(), message_.robots[i].released));
  }
  if (!rq.graphs) {
    report.message = names + ": the running plan has no state graphs to plan on";
    return report;
  }
  // The search gets three quarters of the time: the rest is for checking the new plan and
  // building its dependencies (which walk the whole plan), so that a re-plan ends within it.
  rq.deadline = Deadline::in(0.75 * time_limit);
  rq.seed = (static_cast<std::uint64_t>(plans_) << 20) + message_.revision;
  ReplanResult result = replanRobots(rq);
  report.time_s = result.time_s;
  report.status = result.status;
  message_.last_replan_time = result.time_s;
  if (!result.success()) {
    report.message = names + ": " + statusName(result.status) + ": " + result.reason;
    ++message_.replans_refused;
    message_.last_replan = report.message;
    return report;
  }
  std::vector<int> changed;
  for (int a = 0; a < n; ++a) {
    if (result.plan.paths[a] != plan_.plan.paths[a]) changed.push_back(a);
  }
  plan_.plan = std::move(result.plan);
  plan_.instance = std::move(result.instance);
  for (int a : changed) {
    const auto timeline =
        robotTimeline(plan_.instance.robots[a], plan_.plan.paths[a], *plan_.map, seconds_per_step_);
    auto& poses = plan_.poses[a];
    poses.clear();
    for (const auto& s : timeline.states) {
      geometry_msgs::Pose2D p;
      p.x = s.x, p.y = s.y, p.theta = s.yaw;
      poses.push_back(p);
    }
    matchers_[a] = ProgressMatcher(poses, settings_.position_tolerance, settings_.heading_tolerance);
    message_.robots[a].last_state = static_cast<std::uint32_t>(poses.size() - 1);
    waiting_since_[a] = ros::Time();
  }
  tracker_ = std::make_unique<ExecutionTracker>(plan_.plan, result.dependencies, result.progress);
  cells_.reset();
  message_.dependencies = static_cast<std::uint32_t>(result.dependencies.count());
  message_.done = tracker_->done();
  ++message_.revision;
  ++message_.replans;
  report.merged = true;
  report.robots = changed;
  report.message = names + ": planned in " + std::to_string(result.time_s) + " s (" + result.stages +
                   "; revision " + std::to_string(message_.revision) + ")";
  message_.last_replan = report.message;
  return report;
}

int ExecutionMonitor::released(int robot) const {
  return matchers_[robot].releaseCap(tracker_->progress(robot), tracker_->releasedUpTo(robot));
}

int ExecutionMonitor::progressFrom(int robot, const geometry_msgs::Pose2D& pose) const {
  const int k = matchers_[robot].match(pose, tracker_->progress(robot), released(robot));
  return k < 0 ? tracker_->progress(robot) : k;
}

std::pair<Cell, CellSet> ExecutionMonitor::footprintAt(int robot, const geometry_msgs::Pose2D& pose) const {
  const GridPoint at = toGrid(*plan_.map, pose);
  const Cell cell{static_cast<int>(std::floor(at.x)), static_cast<int>(std::floor(at.y))};
  const Eigen::Vector2d offset(at.x - cell.x - 0.5, at.y - cell.y - 0.5);
  return {cell, footprintCellsAt(plan_.instance.robots[robot].footprint, at.yaw, offset)};
}

const PlanCells& ExecutionMonitor::planCells() {
  if (!cells_) {
    ActionModel model;
    model.step = plan_.lattice_step;
    model.allow_backward = plan_.allow_backward;
    // Only the steps from the smallest progress on are asked about (progress only grows).
    int done = tracker_->progress(0);
    for (int i = 1; i < tracker_->robots(); ++i) done = std::min(done, tracker_->progress(i));
    cells_ = std::make_unique<PlanCells>(plan_.instance, plan_.plan, model, done);
  }
  return *cells_;
}

const std::pair<Cell, CellSet>& ExecutionMonitor::footprintOf(int robot, const Poses& poses,
                                                              Footprints& footprints) const {
  if (!footprints[robot]) footprints[robot].emplace(footprintAt(robot, *poses[robot]));
  return *footprints[robot];
}

std::set<std::pair<int, int>> ExecutionMonitor::overlaps(const Poses& poses, Footprints& footprints) const {
  const GridMap& map = *plan_.map;
  const int n = static_cast<int>(poses.size());
  std::vector<GridPoint> at(n);
  for (int i = 0; i < n; ++i) {
    if (poses[i]) at[i] = toGrid(map, *poses[i]);
  }
  auto cellsOf = [&](int i) -> const std::pair<Cell, CellSet>& { return footprintOf(i, poses, footprints); };
  std::set<std::pair<int, int>> out;
  for (int i = 0; i < n; ++i) {
    if (!poses[i]) continue;
    const double ri = plan_.instance.robots[i].footprint.circumscribedRadius();
    for (int j = i + 1; j < n; ++j) {
      if (!poses[j]) continue;
      const double reach = ri + plan_.instance.robots[j].footprint.circumscribedRadius() + 2.0;
      if (std::hypot(at[i].x - at[j].x, at[i].y - at[j].y) > reach) continue;
      const auto& [ci, si] = cellsOf(i);
      const auto& [cj, sj] = cellsOf(j);
      if (CellSet::overlap(si, ci, sj, cj)) out.insert({i, j});
    }
  }
  return out;
}

fleet_planner::FleetExecution ExecutionMonitor::update(const std::vector<std::optional<geometry_msgs::Pose2D>>& poses,
                                                       const ros::Time& now) {
  const int n = static_cast<int>(ids_.size());
  for (int i = 0; i < n && i < static_cast<int>(poses.size()); ++i) {
    if (poses[i]) tracker_->reportProgress(i, progressFrom(i, *poses[i]));
  }
  // Overlaps: a pair counts once per contact, however long it lasts.
  poses_ = poses;
  // Each robot's footprint where it stands, rasterised when first needed.
  Footprints footprints(poses.size());
  const auto touching = overlaps(poses, footprints);
  new_contacts_.clear();
  auto describe = [&](int i) {
    const auto& p = *poses[i];
    return "'" + ids_[i] + "' at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.theta) +
           "), state " + std::to_string(tracker_->progress(i)) + " of " + std::to_string(tracker_->lastState(i)) +
           ", released " + std::to_string(released(i));
  };
  for (const auto& pair : touching) {
    if (touching_.count(pair)) continue;
    ++message_.collisions;
    new_contacts_.push_back(describe(pair.first) + " and " + describe(pair.second));
  }
  touching_ = touching;

  // Robots off their paths.
  std::vector<bool> off_path(n, false);
  for (int i = 0; i < n && i < static_cast<int>(poses.size()); ++i) {
    off_path[i] = poses[i] && !tracker_->done(i) &&
                  matchers_[i].distanceToPath(*poses[i], tracker_->progress(i), released(i)) >
                      settings_.off_path_tolerance;
  }
  const double elapsed = (now - message_.header.stamp).toSec();
  for (int i = 0; i < n; ++i) {
    auto& r = message_.robots[i];
    const int sent = r.released;
    r.progress = tracker_->progress(i);
    r.released = released(i);
    // Nobody is released into a step that covers where another robot stands (what was released
    // already stays released): a robot off its path stands where the plan does not know it, and
    // the dependencies count a robot past a place once it is within the tolerances of the state
    // after it, when it may still cover a cell of the place. (What it covers on its way on to
    // that state lies within its footprints where it stands and there, but for slivers of a
    // turn's corners far smaller than a cell at the heading tolerance.)
    std::string kept_clear_of;
    const int first_new = std::max<int>(sent, r.progress);
    for (int o = 0; o < n && first_new < static_cast<int>(r.released); ++o) {
      if (o == i || o >= static_cast<int>(poses.size()) || !poses[o]) continue;
      const auto& [cell, set] = footprintOf(o, poses, footprints);
      const PlacedCells there{&set, cell};
      for (int t = first_new; t < static_cast<int>(r.released); ++t) {
        if (!overlap(planCells().during(i, t), there)) continue;
        r.released = t;
        kept_clear_of = ids_[o];
      }
    }
    r.next_waypoint = plan_.poses[i][std::min<int>(r.released, r.progress + 1)];
    const auto holder = tracker_->blockedBy(i);
    const bool held = tracker_->releasedUpTo(i) == static_cast<int>(r.progress);  // not merely not yet released
    r.blocked_by = holder && held ? ids_[holder->robot] : "";
    if (!kept_clear_of.empty() && r.released == r.progress) r.blocked_by = kept_clear_of;
    const int next = std::min<int>(r.progress + 1, r.last_state);
    r.lateness = tracker_->done(i) ? 0.0 : std::max(0.0, elapsed - next * message_.seconds_per_step);
    if (tracker_->done(i)) {
      r.state = RobotExecutionMsg::ARRIVED;
    } else if (i >= static_cast<int>(poses.size()) || !poses[i]) {
      r.state = RobotExecutionMsg::NO_POSE;
    } else if (off_path[i]) {
      r.state = RobotExecutionMsg::OFF_PATH;
    } else if (r.released > r.progress) {
      r.state = RobotExecutionMsg::DRIVING;
    } else {
      r.state = RobotExecutionMsg::WAITING;
    }
    if (r.state == RobotExecutionMsg::WAITING) {
      if (waiting_since_[i].isZero()) waiting_since_[i] = now;
      if ((now - waiting_since_[i]).toSec() > settings_.blocked_timeout) r.state = RobotExecutionMsg::BLOCKED;
    } else {
      waiting_since_[i] = ros::Time();
    }
  }
  message_.done = tracker_->done();
  return message_;
}

diagnostic_msgs::DiagnosticArray executionDiagnostics(const fleet_planner::FleetExecution& execution,
                                                      const ExecutionSettings& settings, const ros::Time& now) {
  using Status = diagnostic_msgs::DiagnosticStatus;
  auto value = [](const std::string& key, const std::string& v) {
    diagnostic_msgs::KeyValue kv;
    kv.key = key, kv.value = v;
    return kv;
  };
  diagnostic_msgs::DiagnosticArray out;
  out.header.stamp = now;
  Status fleet;
  fleet.name = "fleet_planner: execution";
  fleet.hardware_id = "plan " + std::to_string(execution.plan);
  fleet.level = execution.collisions > 0 ? Status::ERROR : Status::OK;
  fleet.message = execution.collisions > 0 ? std::to_string(execution.collisions) + " overlaps of robots seen"
                  : execution.done ? "every robot arrived"
                                   : "executing";
  fleet.values = {value("dependencies", std::to_string(execution.dependencies)),
                  value("collisions", std::to_string(execution.collisions))};
  out.status.push_back(fleet);
  static const char* const kStates[] = {"waiting", "driving", "blocked", "arrived", "no pose", "off its path"};
  for (const auto& r : execution.robots) {
    Status s;
    s.name = "fleet_planner: execution: " + r.robot_id;
    s.hardware_id = r.robot_id;
    s.message = r.state < 6 ? kStates[r.state] : "unknown";
    if (!r.blocked_by.empty()) s.message += " for " + r.blocked_by;
    s.level = r.state == RobotExecutionMsg::NO_POSE || r.state == RobotExecutionMsg::OFF_PATH ? Status::ERROR
              : r.state == RobotExecutionMsg::BLOCKED || r.lateness > settings.late_warning ? Status::WARN
                                                                                             : Status::OK;
    s.values = {value("progress", std::to_string(r.progress)), value("released", std::to_string(r.released)),
                value("last_state", std::to_string(r.last_state)), value("lateness_s", std::to_string(r.lateness)),
                value("blocked_by", r.blocked_by)};
    out.status.push_back(s);
  }
  return out;
}

}  // namespace fleet_planner
