#pragma once
/// The planner node's execution of its last plan (parameter `execute`): at `execution_rate` it
/// reads every robot's pose from TF (map_frame -> <robot_id>/<base_frame>), advances the
/// ExecutionMonitor, and publishes what each robot may drive through:
///   ~execution              fleet_planner/FleetExecution, latched, every update;
///   ~execution/<robot_id>   fleet_planner/RobotExecution, latched, when it changes;
///   /diagnostics            diagnostic_msgs/DiagnosticArray, once a second.
/// A new plan replaces the running one. No exception leaves the timer.
#include <map>
#include <mutex>
#include <optional>
#include <string>

#include <fleet_planner/RobotExecution.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>

#include "fleet_planner/ros/execution_monitor.h"
#include "fleet_planner/ros/planner_config.h"

namespace fleet_planner {

class ExecutionRunner {
 public:
  /// `tf` must outlive the runner.
  ExecutionRunner(ros::NodeHandle nh, ros::NodeHandle private_nh, const PlannerConfig& config, tf2_ros::Buffer& tf);

  /// Executes `plan` from `plan_start` (the stamp of the timelines it was published with).
  void start(const ExecutablePlan& plan, const ros::Time& plan_start);

 private:
  void onTimer(const ros::TimerEvent& event);
  std::optional<geometry_msgs::Pose2D> poseOf(const std::string& robot_id) const;

  const PlannerConfig config_;
  tf2_ros::Buffer& tf_;
  ros::NodeHandle private_nh_;
  ros::Publisher execution_pub_, diagnostics_pub_;
  std::map<std::string, ros::Publisher> robot_pubs_;
  std::map<std::string, fleet_planner::RobotExecution> last_sent_;
  ros::Timer timer_;
  ros::Time last_diagnostics_;
  std::mutex mutex_;  ///< guards the monitor
  ExecutionMonitor monitor_;
};

}  // namespace fleet_planner
