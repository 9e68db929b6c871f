#pragma once
/// Live execution of the last plan (issue: live fleets): each robot's progress from its pose,
/// what it may drive through (the plan's step dependencies, execution/step_dependencies.h),
/// lateness, robots waiting too long, and overlaps of the robots' footprints as they really
/// stand. No ROS master needed: the node feeds it poses and times, gtest does the same.
///
/// A robot's progress comes from its pose (ProgressMatcher: within the tolerances of a state, or
/// on its way to the next); it only goes forward, and only through released states. Robots that stand still are
/// never moved on: a robot that falls behind holds those that must wait for it, nobody else.
/// Nobody is released into a step that covers where another robot stands (what was released
/// already stays released): a robot OFF_PATH stands where its plan does not know it, and a robot
/// counts as at a state within the tolerances of it, so it may not quite have left the cells the
/// step before it covered, which the dependencies take as free.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <fleet_planner/FleetExecution.h>
#include <geometry_msgs/Pose2D.h>
#include <ros/time.h>

#include "fleet_planner/execution/execution_tracker.h"
#include "fleet_planner/execution/plan_cells.h"
#include "fleet_planner/execution/replanning.h"
#include "fleet_planner/ros/conversions.h"
#include "fleet_planner/ros/fleet_planning_service.h"
#include "fleet_planner/ros/progress_matching.h"

namespace fleet_planner {

struct ExecutionSettings {
  double position_tolerance = 0.05;  ///< metres from a state's pose to count as there
  double heading_tolerance = 0.2;    ///< radians
  double blocked_timeout = 10.0;     ///< seconds waiting before a robot is BLOCKED
  double late_warning = 5.0;         ///< seconds late before its diagnostics warn
  double off_path_tolerance = 0.3;   ///< metres from its path (progress to release) before OFF_PATH
};

/// What a re-plan did (ExecutionMonitor::replan).
struct ReplanReport {
  bool merged = false;      ///< the new paths are being executed
  bool nothing_to_do = false;  ///< every robot asked for has arrived
  bool invalid_goal = false;   ///< a new goal off the map or blocked (message says which)
  std::string message;      ///< what was re-planned, or why not (names the robots)
  std::vector<int> robots;  ///< re-planned (plan order)
  SolveStatus status = SolveStatus::Success;
  double time_s = 0.0;
};

class ExecutionMonitor {
 public:
  explicit ExecutionMonitor(ExecutionSettings settings) : settings_(settings) {}

  /// Starts executing `plan` (replacing any running one): every robot at its state 0.
  void start(ExecutablePlan plan, double seconds_per_step, const std::string& map_frame, const ros::Time& now);
  bool running() const { return tracker_ != nullptr; }
  /// The running plan's robot ids, in plan order.
  const std::vector<std::string>& robotIds() const { return ids_; }
  /// The contacts that began at the last update, described ("'a' (state 4 of 30, released 5) and
  /// 'b' (...) share cell (12, 40)"): for the log.
  const std::vector<std::string>& newContacts() const { return new_contacts_; }
  /// Requirements between the running plan's steps (FleetExecution::dependencies).
  std::uint32_t dependencies() const { return message_.dependencies; }
  /// The running plan, with the re-plans merged into it.
  const ExecutablePlan& plan() const { return plan_; }
  /// Re-plans merged into the running plan.
  std::uint32_t revision() const { return message_.revision; }
  /// When the running plan started (its timelines' stamp).
  const ros::Time& stamp() const { return message_.header.stamp; }
  /// Robots BLOCKED at the last update (plan order).
  std::vector<int> blockedRobots() const;
  /// Robots OFF_PATH at the last update (plan order).
  std::vector<int> offPathRobots() const;

  /// Plans `robots` again from the states they have reached (execution/replanning.h), each around
  /// the next steps of the robot it waits for, within `time_limit` seconds; merges the new paths
  /// when they keep every other robot released as far as it is. A robot OFF_PATH at the last
  /// update is planned from its pose then (snapped within `tolerance`; ReplanRequest::moved).
  /// Requires running().
  ReplanReport replan(const std::vector<int>& robots, double time_limit, const PoseTolerance& tolerance);
  /// New goals (map frame, any yaw) for some robots, planned like replan() (replanning.h: new
  /// targets). A goal that cannot be put on the map within `tolerance` is refused (invalid_goal).
  ReplanReport assignGoals(const std::vector<std::pair<int, geometry_msgs::Pose2D>>& goals, double time_limit,
                           const PoseTolerance& tolerance);

  /// One update from the robots' current poses (plan order; nullopt: no pose known).
  /// Returns the execution's state. Requires running().
  fleet_planner::FleetExecution update(const std::vector<std::optional<geometry_msgs::Pose2D>>& poses,
                                       const ros::Time& now);

 private:
  /// Plans `rq` (robots, targets, avoid; the rest filled in here) and merges it on success.
  ReplanReport replanWith(ReplanRequest rq, const std::string& names, double time_limit);
  int progressFrom(int robot, const geometry_msgs::Pose2D& pose) const;
  /// What the robot may drive through now: the dependencies' release, capped where its pose
  /// would be ambiguous (ProgressMatcher::releaseCap).
  int released(int robot) const;
  using Poses = std::vector<std::optional<geometry_msgs::Pose2D>>;
  /// Per robot, its footprint at its pose, once rasterised (footprintOf).
  using Footprints = std::vector<std::optional<std::pair<Cell, CellSet>>>;
  /// Robot's footprint at poses[robot] (which must be known), rasterised into `footprints` once.
  const std::pair<Cell, CellSet>& footprintOf(int robot, const Poses& poses, Footprints& footprints) const;
  /// Pairs of robots (i < j) whose footprints at their poses share a map cell.
  std::set<std::pair<int, int>> overlaps(const Poses& poses, Footprints& footprints) const;
  /// Robots in RobotExecution state `state` at the last update (plan order).
  std::vector<int> robotsIn(std::uint8_t state) const;
  /// The map cells robot i's footprint covers at `pose`: a set relative to a cell.
  std::pair<Cell, CellSet> footprintAt(int robot, const geometry_msgs::Pose2D& pose) const;
  /// The running plan's cells from the smallest progress on (built when first needed after a
  /// start or a merge).
  const PlanCells& planCells();

  ExecutionSettings settings_;
  ExecutablePlan plan_;
  std::unique_ptr<ExecutionTracker> tracker_;
  std::vector<ProgressMatcher> matchers_;  ///< per robot
  std::vector<std::string> ids_;
  fleet_planner::FleetExecution message_;
  std::vector<ros::Time> waiting_since_;  ///< when each robot last stood at its release (zero: driving)
  std::set<std::pair<int, int>> touching_;  ///< overlapping pairs at the last update
  std::vector<std::string> new_contacts_;
  std::vector<std::optional<geometry_msgs::Pose2D>> poses_;  ///< at the last update
  std::unique_ptr<PlanCells> cells_;  ///< of plan_ (null: not built yet)
  std::uint32_t plans_ = 0;
  double seconds_per_step_ = 1.0;
};

/// One status per robot (OK, WARN when late or blocked, ERROR without a pose) and one for the
/// fleet (ERROR once robots overlapped), as diagnostic_msgs for rqt and the aggregator.
diagnostic_msgs::DiagnosticArray executionDiagnostics(const fleet_planner::FleetExecution& execution,
                                                      const ExecutionSettings& settings, const ros::Time& now);

}  // namespace fleet_planner
