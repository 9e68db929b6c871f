#include "fleet_planner/ros/planner_node.h"

#include <chrono>
#include <cstdio>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <tf2/LinearMath/Quaternion.h>
#include <tf2/utils.h>
#include <visualization_msgs/MarkerArray.h>

#include "fleet_planner/ros/marker_builder.h"
#include "fleet_planner/ros/path_messages.h"
#include "fleet_planner/ros/plan_playback.h"

namespace fleet_planner {

namespace {

constexpr double kPlaybackHz = 20.0;
constexpr double kLoopPause = 2.0;  // seconds at the end before playing again

}  // namespace

PlannerNode::PlannerNode(ros::NodeHandle nh, ros::NodeHandle private_nh, PlannerConfig config)
    : nh_(nh), private_nh_(private_nh), service_(std::move(config)), tf_listener_(tf_buffer_) {
  timelines_pub_ = private_nh_.advertise<fleet_planner::FleetTimelines>("timelines", 1, true);
  markers_pub_ = private_nh_.advertise<visualization_msgs::MarkerArray>("markers", 1, true);
  map_sub_ = nh_.subscribe("map", 1, &PlannerNode::onMap, this);
  fleet_sub_ = nh_.subscribe("fleet_footprints", 1, &PlannerNode::onFootprints, this);
  auto options = ros::AdvertiseServiceOptions::create<fleet_planner::PlanFleet>(
      "plan_fleet",
      [this](fleet_planner::PlanFleet::Request& request, fleet_planner::PlanFleet::Response& response) {
        return onPlanFleet(request, response);
      },
      ros::VoidConstPtr(), &service_queue_);
  plan_server_ = private_nh_.advertiseService(options);
  service_spinner_.start();
  if (service_.config().execute) {
    execution_ = std::make_unique<ExecutionRunner>(nh_, private_nh_, service_.config(), tf_buffer_);
    execution_->onRevised([this](const ExecutablePlan& plan, std::uint32_t revision, const ros::Time& plan_start) {
      publishRevision(plan, revision, plan_start);
    });
    auto replan = ros::AdvertiseServiceOptions::create<fleet_planner::ReplanRobots>(
        "replan",
        [this](fleet_planner::ReplanRobots::Request& request, fleet_planner::ReplanRobots::Response& response) {
          response = execution_->replan(request);
          return true;
        },
        ros::VoidConstPtr(), &service_queue_);
    replan_server_ = private_nh_.advertiseService(replan);
    auto add_tasks = ros::AdvertiseServiceOptions::create<fleet_planner::AddTasks>(
        "add_tasks",
        [this](fleet_planner::AddTasks::Request& request, fleet_planner::AddTasks::Response& response) {
          response = execution_->addTasks(request);
          return true;
        },
        ros::VoidConstPtr(), &service_queue_);
    add_tasks_server_ = private_nh_.advertiseService(add_tasks);
  }
  if (service_.config().playback) {
    playback_timer_ = nh_.createTimer(ros::Duration(1.0 / kPlaybackHz), &PlannerNode::onPlaybackTimer, this);
  }
}

PlannerNode::~PlannerNode() {
  shutting_down_ = true;  // a running plan stops at its next deadline check
  plan_server_.shutdown();
  service_spinner_.stop();
}

void PlannerNode::onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
  try {
    service_.setMap(*msg);
    ROS_INFO("fleet_planner: map %u x %u cells of %.3f m", msg->info.width, msg->info.height, msg->info.resolution);
  } catch (const std::exception& e) {
    ROS_ERROR("fleet_planner: map rejected, keeping the previous one: %s", e.what());
  }
}

void PlannerNode::onFootprints(const fleet_planner::FleetFootprints::ConstPtr& msg) {
  try {
    service_.setFootprints(*msg);
    ROS_INFO("fleet_planner: footprint registry with %zu robots", msg->robots.size());
  } catch (const std::exception& e) {
    ROS_ERROR("fleet_planner: footprint registry rejected: %s", e.what());
  }
}

bool PlannerNode::lookupStart(const std::string& robot_id, geometry_msgs::Pose2D& pose, std::string& error) {
  const auto& c = service_.config();
  const std::string frame = robot_id + "/" + c.base_frame;
  try {
    const auto t = tf_buffer_.lookupTransform(c.map_frame, frame, ros::Time(0), ros::Duration(c.tf_timeout));
    pose.x = t.transform.translation.x;
    pose.y = t.transform.translation.y;
    pose.theta = tf2::getYaw(t.transform.rotation);
    return true;
  } catch (const std::exception& e) {
    error = "no transform " + c.map_frame + " -> " + frame + ": " + e.what();
    return false;
  }
}

bool PlannerNode::onPlanFleet(fleet_planner::PlanFleet::Request& request, fleet_planner::PlanFleet::Response& response) {
  using Response = fleet_planner::PlanFleet::Response;
  const auto received = FleetPlanningService::Clock::now();
  try {
    if (auto bad = service_.checkRequest(request)) {  // answered at once, even while busy
      response = std::move(*bad);
      ROS_INFO("fleet_planner: %zu robots: %s: %s", request.tasks.size(), fleetStatusName(response.status).c_str(),
               response.message.c_str());
      return true;
    }
    std::unique_lock<std::timed_mutex> lock(plan_mutex_, std::defer_lock);
    if (service_.config().busy_policy == "queue") {
      // Wait for the running call(s), but no longer than this call's own time limit.
      const double limit = service_.timeLimit(request);
      const auto until = received + std::chrono::duration_cast<FleetPlanningService::Clock::duration>(
                                        std::chrono::duration<double>(limit));
      if (!lock.try_lock_until(until)) {
        char text[160];
        std::snprintf(text, sizeof(text),
                      "time_limit (%g s) passed while waiting for other PlanFleet calls to finish (busy_policy: queue)",
                      limit);
        response.status = Response::TIMEOUT;
        response.message = text;
        response.statistics.robots = static_cast<std::uint32_t>(request.tasks.size());
        response.statistics.soc = response.statistics.makespan = -1;
        response.statistics.total_time =
            std::chrono::duration<double>(FleetPlanningService::Clock::now() - received).count();
        ROS_WARN("fleet_planner: %s", response.message.c_str());
        return true;
      }
    } else if (!lock.try_lock()) {
      response.status = Response::BUSY;
      response.message = "another PlanFleet call is planning (busy_policy: reject); call again later";
      return true;
    }
    const PlanCall call = service_.plan(
        request, [this](const std::string& id, geometry_msgs::Pose2D& p, std::string& e) { return lookupStart(id, p, e); },
        &shutting_down_, received);
    response = call.response;
    const auto& r = call.response;
    ROS_INFO("fleet_planner: %zu robots: %s: %s (%.2f s)", request.tasks.size(), fleetStatusName(r.status).c_str(),
             r.message.c_str(), r.statistics.total_time);
    publish(call);
#ifdef __GLIBC__
    // Planning frees hundreds of MB in the worker threads' arenas: give them back to the system,
    // so that a node that plans all day does not keep its largest call's peak.
    malloc_trim(0);
#endif
  } catch (const std::exception& e) {
    response.status = Response::INTERNAL_ERROR;
    response.message = std::string("internal error: ") + e.what();
    ROS_ERROR("fleet_planner: %s", response.message.c_str());
  }
  return true;  // the answer is in the response, whatever happened
}

void PlannerNode::publish(const PlanCall& call) {
  const auto& c = service_.config();
  const auto& r = call.response;
  MarkerStyle style;
  style.map_frame = c.map_frame;
  // The robots' markers ride on their frames: the real robots' while executing, else the playback's.
  if (r.status == fleet_planner::PlanFleet::Response::SUCCESS) {
    if (c.execute) {
      style.planned_frame_suffix = c.base_frame;
    } else if (c.playback) {
      style.planned_frame_suffix = c.planned_frame;
    }
  }
  const ros::Time now = ros::Time::now();
  publishMarkers(buildPlanMarkers(call.placements, r.timelines, r.subproblems, style), now);
  if (r.status != fleet_planner::PlanFleet::Response::SUCCESS) return;

  fleet_planner::FleetTimelines timelines;
  timelines.header.frame_id = c.map_frame;
  timelines.header.stamp = now;
  timelines.seconds_per_step = c.seconds_per_step;
  timelines.timelines = r.timelines;
  {
    std::lock_guard<std::mutex> lock(timelines_mutex_);
    timelines_pub_.publish(timelines);
    timelines_ = timelines;
    placements_ = call.placements;
    subproblems_ = r.subproblems;
    marker_style_ = style;
    // Each robot's plan as a nav_msgs/Path, stamped with its planned times (latched, one topic each).
    for (const auto& timeline : r.timelines) {
      auto pub = path_pubs_.find(timeline.robot_id);
      if (pub == path_pubs_.end()) {
        pub = path_pubs_.emplace(timeline.robot_id,
                                 private_nh_.advertise<nav_msgs::Path>(planTopicName(timeline.robot_id), 1, true)).first;
      }
      pub->second.publish(toPathMessage(timeline, c.map_frame, now, c.seconds_per_step));
    }
  }
  if (execution_ && call.executable) execution_->start(*call.executable, now);
  std::lock_guard<std::mutex> lock(playback_mutex_);
  playing_ = r.timelines;
  playback_start_ = now;
}

void PlannerNode::publishMarkers(visualization_msgs::MarkerArray markers, const ros::Time& now) {
  for (auto& m : markers.markers) {
    if (!m.frame_locked) m.header.stamp = now;  // frame-locked ones use the latest transform (stamp 0)
  }
  markers_pub_.publish(markers);
}

void PlannerNode::publishRevision(const ExecutablePlan& plan, std::uint32_t revision, const ros::Time& plan_start) {
  const auto& c = service_.config();
  std::lock_guard<std::mutex> lock(timelines_mutex_);
  if (timelines_.header.stamp != plan_start || timelines_.timelines.size() != plan.plan.paths.size()) {
    return;  // not the plan published last
  }
  timelines_.revision = revision;
  for (std::size_t i = 0; i < plan.plan.paths.size(); ++i) {
    auto& timeline = timelines_.timelines[i];
    const Path& path = plan.plan.paths[i];
    bool same = timeline.states.size() == path.size();
    for (std::size_t t = 0; same && t < path.size(); ++t) {
      const auto& s = timeline.states[t];
      same = s.cell_x == path[t].x && s.cell_y == path[t].y && s.heading == path[t].heading;
    }
    if (same) continue;
    const int subproblem = timeline.subproblem;
    timeline = robotTimeline(plan.instance.robots[i], path, *plan.map, c.seconds_per_step);
    timeline.subproblem = subproblem;
    auto pub = path_pubs_.find(timeline.robot_id);
    if (pub != path_pubs_.end()) {
      pub->second.publish(toPathMessage(timeline, c.map_frame, timelines_.header.stamp, c.seconds_per_step));
    }
  }
  timelines_pub_.publish(timelines_);
  publishMarkers(buildPlanMarkers(placements_, timelines_.timelines, subproblems_, marker_style_), ros::Time::now());
}

void PlannerNode::onPlaybackTimer(const ros::TimerEvent&) {
  try {
    const auto& c = service_.config();
    std::lock_guard<std::mutex> lock(playback_mutex_);
    if (playing_.empty()) return;
    const ros::Time now = ros::Time::now();
    double t = (now - playback_start_).toSec() * c.playback_rate;
    const double duration = planDuration(playing_);
    if (c.playback_loop && t > duration + kLoopPause * c.playback_rate) {
      playback_start_ = now;
      t = 0.0;
    }
    std::vector<geometry_msgs::TransformStamped> transforms;
    for (const auto& timeline : playing_) {
      if (timeline.states.empty()) continue;
      const auto pose = poseAt(timeline, t);
      geometry_msgs::TransformStamped tf;
      tf.header.stamp = now;
      tf.header.frame_id = c.map_frame;
      tf.child_frame_id = timeline.robot_id + "/" + c.planned_frame;
      tf.transform.translation.x = pose.x;
      tf.transform.translation.y = pose.y;
      tf2::Quaternion q;
      q.setRPY(0, 0, pose.theta);
      tf.transform.rotation.x = q.x(), tf.transform.rotation.y = q.y();
      tf.transform.rotation.z = q.z(), tf.transform.rotation.w = q.w();
      transforms.push_back(tf);
    }
    tf_broadcaster_.sendTransform(transforms);
  } catch (const std::exception& e) {
    ROS_ERROR_THROTTLE(5.0, "fleet_planner: playback: %s", e.what());
  }
}

}  // namespace fleet_planner
