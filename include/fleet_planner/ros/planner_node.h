#pragma once
/// fleet_planner_node: the ROS face of the planner. Subscribes to the map and the footprint
/// registry, offers ~plan_fleet, publishes the last plan's timelines and markers (latched) and
/// plays the plan back as TF frames <robot>/<planned_frame>.
///
/// Threads: PlanFleet calls have their own callback queue and two threads, so map, registry and
/// playback callbacks (on the node's spinner) never wait for a plan, and a map update is taken
/// while a call plans (the running call keeps its snapshot). A bad request is answered at once,
/// busy or not. One call plans at a time; a second one is answered BUSY (busy_policy: reject) or
/// waits its turn (busy_policy: queue), at most its time limit: waiting counts against it, and a
/// call whose time runs out in the queue is answered TIMEOUT. No exception leaves a callback.
#include <atomic>
#include <memory>
#include <mutex>

#include <fleet_planner/FleetFootprints.h>
#include <fleet_planner/FleetTimelines.h>
#include <fleet_planner/PlanFleet.h>
#include <nav_msgs/OccupancyGrid.h>
#include <map>
#include <string>

#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include "fleet_planner/ros/backend_loader.h"
#include "fleet_planner/ros/execution_runner.h"
#include "fleet_planner/ros/fleet_planning_service.h"
#include "fleet_planner/ros/marker_builder.h"
#include <visualization_msgs/MarkerArray.h>

namespace fleet_planner {

class PlannerNode {
 public:
  /// `nh` for topics, `private_nh` for the service and the latched outputs. The config must have
  /// passed checkPlannerConfig(); `plugins` must outlive the node.
  PlannerNode(ros::NodeHandle nh, ros::NodeHandle private_nh, PlannerConfig config);
  ~PlannerNode();

 private:
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg);
  void onFootprints(const fleet_planner::FleetFootprints::ConstPtr& msg);
  bool onPlanFleet(fleet_planner::PlanFleet::Request& request, fleet_planner::PlanFleet::Response& response);
  bool lookupStart(const std::string& robot_id, geometry_msgs::Pose2D& pose, std::string& error);
  void publish(const PlanCall& call);
  /// A re-plan merged into the running plan: its timelines and paths again, same stamp.
  /// The plan's markers, stamped `now` (but the frame-locked ones).
  void publishMarkers(visualization_msgs::MarkerArray markers, const ros::Time& now);
  void publishRevision(const ExecutablePlan& plan, std::uint32_t revision, const ros::Time& plan_start);
  void onPlaybackTimer(const ros::TimerEvent& event);

  ros::NodeHandle nh_, private_nh_;
  ros::CallbackQueue service_queue_;  ///< PlanFleet calls only
  ros::AsyncSpinner service_spinner_{2, &service_queue_};
  FleetPlanningService service_;
  std::atomic<bool> shutting_down_{false};
  std::timed_mutex plan_mutex_;  ///< held while a call plans

  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  ros::Subscriber map_sub_, fleet_sub_;
  ros::ServiceServer plan_server_, replan_server_, add_tasks_server_;
  ros::Publisher timelines_pub_, markers_pub_;
  std::map<std::string, ros::Publisher> path_pubs_;  ///< ~plans/<robot_id>, latched, by robot id
  ros::Timer playback_timer_;

  std::unique_ptr<ExecutionRunner> execution_;  ///< with parameter `execute`

  std::mutex timelines_mutex_;  ///< guards the plan as published (the five below) and path_pubs_
  fleet_planner::FleetTimelines timelines_;  ///< as last published
  std::vector<RobotPlacement> placements_;   ///< of the last plan, for its markers
  std::vector<fleet_planner::SubproblemInfo> subproblems_;
  MarkerStyle marker_style_;

  std::mutex playback_mutex_;  ///< guards the two below
  std::vector<fleet_planner::RobotTimeline> playing_;
  ros::Time playback_start_;
};

}  // namespace fleet_planner
