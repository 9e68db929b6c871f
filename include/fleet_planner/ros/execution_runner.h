#pragma once
/// The planner node's execution of its last plan (parameter `execute`): at `execution_rate` it
/// reads every robot's pose from TF (map_frame -> <robot_id>/<base_frame>), advances the
/// ExecutionMonitor, and publishes what each robot may drive through:
///   ~execution              fleet_planner/FleetExecution, latched, every update;
///   ~execution/<robot_id>   fleet_planner/RobotExecution, latched, when it changes;
///   /diagnostics            diagnostic_msgs/DiagnosticArray, once a second.
/// A new plan replaces the running one. With `replan_blocked`, a robot BLOCKED for longer than
/// blocked_timeout is planned again around the robot it waits for, and with `replan_off_path` a
/// robot OFF_PATH from the pose where it stands (ExecutionMonitor::replan; each robot at most
/// once per blocked_timeout, less often after refusals while what it waits for stands still:
/// replan_backoff.h; one re-plan per update); a merged re-plan is handed to `on_revised`
/// (the node publishes the revised timelines). No exception leaves the timer.
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>

#include <fleet_planner/AddTasks.h>
#include <fleet_planner/ReplanRobots.h>
#include <fleet_planner/RobotExecution.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>

#include "fleet_planner/ros/execution_monitor.h"
#include "fleet_planner/ros/planner_config.h"
#include "fleet_planner/ros/replan_backoff.h"

namespace fleet_planner {

class ExecutionRunner {
 public:
  /// `tf` must outlive the runner.
  ExecutionRunner(ros::NodeHandle nh, ros::NodeHandle private_nh, const PlannerConfig& config, tf2_ros::Buffer& tf);

  /// Executes `plan` from `plan_start` (the stamp of the timelines it was published with).
  void start(const ExecutablePlan& plan, const ros::Time& plan_start);

  /// Called with the running plan and its revision after each merged re-plan (under the
  /// runner's lock: do not call back into the runner).
  using RevisionCallback =
      std::function<void(const ExecutablePlan& plan, std::uint32_t revision, const ros::Time& plan_start)>;
  void onRevised(RevisionCallback callback);

  /// The ~replan service: re-plans the robots named (empty: every BLOCKED one). Never throws.
  fleet_planner::ReplanRobots::Response replan(const fleet_planner::ReplanRobots::Request& request);
  /// The ~add_tasks service: new goals for robots of the running plan. Never throws.
  fleet_planner::AddTasks::Response addTasks(const fleet_planner::AddTasks::Request& request);

 private:
  void onTimer(const ros::TimerEvent& event);
  /// Re-plans `robots` (monitor lock held) and reports a merge.
  ReplanReport replanLocked(const std::vector<int>& robots, double time_limit);
  /// Logs a re-plan, hands a merge to on_revised_ and gives freed memory back (lock held).
  void reported(const ReplanReport& report);
  /// A service call under the lock: NOT_EXECUTING, INVALID_REQUEST for a bad time_limit, NO_PLAN
  /// for an exception; else body(response, time limit in seconds).
  template <class Response, class Body>
  Response serve(const char* name, double time_limit, Body&& body);
  std::optional<geometry_msgs::Pose2D> poseOf(const std::string& robot_id) const;

  const PlannerConfig config_;
  tf2_ros::Buffer& tf_;
  ros::NodeHandle private_nh_;
  ros::Publisher execution_pub_, diagnostics_pub_, markers_pub_;
  std::map<std::string, ros::Publisher> robot_pubs_;
  std::map<std::string, fleet_planner::RobotExecution> last_sent_;
  ros::Timer timer_;
  ros::Time last_diagnostics_, last_markers_;
  std::mutex mutex_;  ///< guards the monitor
  ExecutionMonitor monitor_;
  RevisionCallback on_revised_;
  /// Per robot and reason ("<id> blocked", "<id> off path"): when its next automatic re-plan is
  /// due. A robot re-planned while BLOCKED may leave its path right after, and is then planned
  /// again at once.
  ReplanBackoff backoff_;
};

}  // namespace fleet_planner
