#include "fleet_planner/ros/execution_runner.h"

#include <algorithm>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <tf2/utils.h>

#include "fleet_planner/ros/marker_builder.h"
#include "fleet_planner/ros/path_messages.h"

namespace fleet_planner {

namespace {

// A refused automatic re-plan waits up to this many blocked_timeouts before it is tried again
// with nothing changed (replan_backoff.h).
constexpr double kMaxBackoff = 4.0;

ExecutionSettings executionSettings(const PlannerConfig& c) {
  ExecutionSettings s;
  s.position_tolerance = c.progress_tolerance;
  s.heading_tolerance = c.progress_heading_tolerance;
  s.blocked_timeout = c.blocked_timeout;
  s.late_warning = c.late_warning;
  s.off_path_tolerance = c.off_path_tolerance;
  return s;
}

// What a refused re-plan of robot a depended on. BLOCKED: the robot it waits for and that
// robot's progress. OFF_PATH: everybody's progress (it is refused while someone has still to
// pass where it stands, which changes as any robot moves on).
std::string replanCause(const fleet_planner::FleetExecution& execution, int a, bool off_path) {
  if (off_path) {
    unsigned long long done = 0;
    for (const auto& robot : execution.robots) done += robot.progress;
    return "fleet@" + std::to_string(done);
  }
  const std::string& awaited = execution.robots[a].blocked_by;
  for (const auto& robot : execution.robots) {
    if (!awaited.empty() && robot.robot_id == awaited) return awaited + "@" + std::to_string(robot.progress);
  }
  return awaited;
}

bool sameRelease(const fleet_planner::RobotExecution& a, const fleet_planner::RobotExecution& b) {
  return a.state == b.state && a.progress == b.progress && a.released == b.released && a.blocked_by == b.blocked_by;
}

}  // namespace

ExecutionRunner::ExecutionRunner(ros::NodeHandle nh, ros::NodeHandle private_nh, const PlannerConfig& config,
                                 tf2_ros::Buffer& tf)
    : config_(config),
      tf_(tf),
      private_nh_(private_nh),
      monitor_(executionSettings(config)),
      backoff_(config.blocked_timeout, kMaxBackoff * config.blocked_timeout) {
  execution_pub_ = private_nh_.advertise<fleet_planner::FleetExecution>("execution", 1, true);
  diagnostics_pub_ = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
  markers_pub_ = private_nh_.advertise<visualization_msgs::MarkerArray>("execution_markers", 1, true);
  timer_ = nh.createTimer(ros::Duration(1.0 / config.execution_rate), &ExecutionRunner::onTimer, this);
}

void ExecutionRunner::start(const ExecutablePlan& plan, const ros::Time& plan_start) {
  std::lock_guard<std::mutex> lock(mutex_);
  monitor_.start(plan, config_.seconds_per_step, config_.map_frame, plan_start);
  last_sent_.clear();
  backoff_.clear();
  for (const std::string& id : monitor_.robotIds()) {
    if (!robot_pubs_.count(id)) {
      robot_pubs_.emplace(id, private_nh_.advertise<fleet_planner::RobotExecution>(robotTopicName("execution", id), 1,
                                                                                  true));
    }
  }
  ROS_INFO("fleet_planner: executing the plan of %zu robots (%u dependencies between their steps)",
           monitor_.robotIds().size(), monitor_.dependencies());
}

void ExecutionRunner::onRevised(RevisionCallback callback) {
  std::lock_guard<std::mutex> lock(mutex_);
  on_revised_ = std::move(callback);
}

ReplanReport ExecutionRunner::replanLocked(const std::vector<int>& robots, double time_limit) {
  ReplanReport report = monitor_.replan(robots, time_limit, config_.poseTolerance());
  reported(report);
  return report;
}

void ExecutionRunner::reported(const ReplanReport& report) {
  if (report.merged) {
    ROS_INFO("fleet_planner: execution: %s", report.message.c_str());
    if (on_revised_) on_revised_(monitor_.plan(), monitor_.revision(), monitor_.stamp());
  } else if (!report.nothing_to_do) {
    ROS_WARN("fleet_planner: execution: %s", report.message.c_str());
  }
#ifdef __GLIBC__
  malloc_trim(0);  // a re-plan's tables are large and short-lived: a node re-planning all day keeps no peak
#endif
}

namespace {

/// A service's answer from a re-plan's report (`robots`: its list of robot ids).
template <class Response>
void answer(const ReplanReport& report, const std::vector<std::string>& ids, Response& response,
            std::vector<std::string>& robots) {
  response.message = report.message;
  response.time = report.time_s;
  for (int a : report.robots) robots.push_back(ids[a]);
}

}  // namespace

template <class Response, class Body>
Response ExecutionRunner::serve(const char* name, double time_limit, Body&& body) {
  Response response;
  try {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!monitor_.running()) {
      response.status = Response::NOT_EXECUTING;
      response.message = "no plan is being executed";
    } else if (!(time_limit >= 0.0) || time_limit > 3600.0) {
      response.status = Response::INVALID_REQUEST;
      response.message = "time_limit must be in [0, 3600] s (0: the replan_time_limit parameter)";
    } else {
      body(response, time_limit > 0.0 ? time_limit : config_.replan_time_limit);
    }
  } catch (const std::exception& e) {
    response.status = Response::NO_PLAN;
    response.message = std::string("internal error: ") + e.what();
    ROS_ERROR("fleet_planner: %s: %s", name, response.message.c_str());
  }
  return response;
}

fleet_planner::AddTasks::Response ExecutionRunner::addTasks(const fleet_planner::AddTasks::Request& request) {
  using Response = fleet_planner::AddTasks::Response;
  return serve<Response>("add_tasks", request.time_limit, [&](Response& response, double time_limit) {
    auto invalid = [&](const std::string& why) {
      response.status = Response::INVALID_REQUEST;
      response.message = why;
    };
    if (request.tasks.empty()) return invalid("no task");
    const auto& ids = monitor_.robotIds();
    std::vector<std::pair<int, geometry_msgs::Pose2D>> goals;
    for (const auto& task : request.tasks) {
      const auto it = std::find(ids.begin(), ids.end(), task.robot_id);
      if (it == ids.end()) return invalid("robot '" + task.robot_id + "' is not in the running plan");
      const int a = static_cast<int>(it - ids.begin());
      for (const auto& g : goals) {
        if (g.first == a) return invalid("robot '" + task.robot_id + "' has two tasks");
      }
      goals.emplace_back(a, task.goal);
    }
    const ReplanReport report = monitor_.assignGoals(goals, time_limit, config_.poseTolerance());
    reported(report);
    response.status = report.merged ? Response::SUCCESS : report.invalid_goal ? Response::INVALID_REQUEST : Response::NO_PLAN;
    answer(report, ids, response, response.planned);
  });
}

fleet_planner::ReplanRobots::Response ExecutionRunner::replan(const fleet_planner::ReplanRobots::Request& request) {
  using Response = fleet_planner::ReplanRobots::Response;
  return serve<Response>("replan", request.time_limit, [&](Response& response, double time_limit) {
    std::vector<int> robots;
    const auto& ids = monitor_.robotIds();
    for (const std::string& id : request.robot_ids) {
      const auto it = std::find(ids.begin(), ids.end(), id);
      if (it == ids.end()) {
        response.status = Response::INVALID_REQUEST;
        response.message = "robot '" + id + "' is not in the running plan";
        return;
      }
      robots.push_back(static_cast<int>(it - ids.begin()));
    }
    if (request.robot_ids.empty()) robots = monitor_.blockedRobots();
    if (robots.empty()) {
      response.status = Response::NOTHING_TO_DO;
      response.message = "no robot is BLOCKED";
      return;
    }
    const ReplanReport report = replanLocked(robots, time_limit);
    response.status = report.merged ? Response::SUCCESS : report.nothing_to_do ? Response::NOTHING_TO_DO : Response::NO_PLAN;
    answer(report, ids, response, response.replanned);
  });
}

std::optional<geometry_msgs::Pose2D> ExecutionRunner::poseOf(const std::string& robot_id) const {
  try {
    const auto t = tf_.lookupTransform(config_.map_frame, robot_id + "/" + config_.base_frame, ros::Time(0));
    geometry_msgs::Pose2D pose;
    pose.x = t.transform.translation.x;
    pose.y = t.transform.translation.y;
    pose.theta = tf2::getYaw(t.transform.rotation);
    return pose;
  } catch (const std::exception&) {
    return std::nullopt;  // reported as NO_POSE
  }
}

void ExecutionRunner::onTimer(const ros::TimerEvent&) {
  try {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!monitor_.running()) return;
    std::vector<std::optional<geometry_msgs::Pose2D>> poses;
    for (const std::string& id : monitor_.robotIds()) poses.push_back(poseOf(id));
    const ros::Time now = ros::Time::now();
    fleet_planner::FleetExecution execution = monitor_.update(poses, now);
    for (const std::string& contact : monitor_.newContacts()) ROS_WARN("fleet_planner: execution: contact: %s", contact.c_str());
    // Each robot BLOCKED for longer than blocked_timeout or OFF_PATH, when its backoff allows,
    // and one re-plan per update: the lock (and the service calls waiting for it) is held for at
    // most one replan_time_limit, and the other robots get their turns next.
    std::vector<std::pair<int, bool>> candidates;  // (robot, off its path)
    if (config_.replan_off_path) {
      for (int a : monitor_.offPathRobots()) candidates.emplace_back(a, true);
    }
    if (config_.replan_blocked) {
      for (int a : monitor_.blockedRobots()) candidates.emplace_back(a, false);
    }
    for (const auto& [a, off_path] : candidates) {
      const std::string key = monitor_.robotIds()[a] + (off_path ? " off path" : " blocked");
      const std::string cause = replanCause(execution, a, off_path);
      if (!backoff_.due(key, now.toSec(), cause)) continue;
      const bool merged = replanLocked({a}, config_.replan_time_limit).merged;
      backoff_.record(key, now.toSec(), cause, merged);
      if (merged) execution = monitor_.update(poses, ros::Time::now());
      break;
    }
    execution_pub_.publish(execution);
    for (const auto& robot : execution.robots) {
      auto sent = last_sent_.find(robot.robot_id);
      if (sent != last_sent_.end() && sameRelease(sent->second, robot)) continue;
      robot_pubs_[robot.robot_id].publish(robot);
      last_sent_[robot.robot_id] = robot;
    }
    if ((now - last_markers_).toSec() >= 0.5) {
      markers_pub_.publish(buildExecutionMarkers(execution, config_.base_frame, config_.late_warning));
      last_markers_ = now;
    }
    if ((now - last_diagnostics_).toSec() >= 1.0) {
      diagnostics_pub_.publish(executionDiagnostics(execution, executionSettings(config_), now));
      last_diagnostics_ = now;
    }
  } catch (const std::exception& e) {
    ROS_ERROR_THROTTLE(5.0, "fleet_planner: execution: %s", e.what());
  }
}

}  // namespace fleet_planner
