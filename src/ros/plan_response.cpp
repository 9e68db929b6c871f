// Building PlanFleet responses; see plan_response.h.
#include "plan_response.h"

#include <algorithm>

#include "fleet_planner/model/robot_cells.h"
#include "fleet_planner/ros/conversions.h"
#include "fleet_planner/ros/path_messages.h"

namespace fleet_planner {

namespace {

using Response = fleet_planner::PlanFleet::Response;
using RobotResultMsg = fleet_planner::RobotResult;

/// Fleet status for the first robot error of each kind, most fundamental first.
std::uint8_t fleetStatusFor(std::uint8_t robot_status) {
  switch (robot_status) {
    case RobotResultMsg::UNKNOWN_ROBOT: return Response::UNKNOWN_ROBOT;
    case RobotResultMsg::INVALID_FOOTPRINT: return Response::INVALID_REQUEST;
    case RobotResultMsg::NO_TRANSFORM: return Response::NO_TRANSFORM;
    case RobotResultMsg::INVALID_START: return Response::INVALID_START;
    case RobotResultMsg::INVALID_GOAL: return Response::INVALID_GOAL;
    case RobotResultMsg::UNREACHABLE: return Response::INFEASIBLE;
    default: return Response::INVALID_REQUEST;
  }
}

}  // namespace

void fail(PlanCall& call, std::uint8_t status, const std::string& message) {
  call.response.status = status;
  call.response.message = message;
}

bool failOnRobotErrors(PlanCall& call) {
  auto& robots = call.response.robots;
  const std::uint8_t order[] = {RobotResultMsg::UNKNOWN_ROBOT, RobotResultMsg::INVALID_FOOTPRINT,
                                RobotResultMsg::NO_TRANSFORM,  RobotResultMsg::INVALID_START,
                                RobotResultMsg::INVALID_GOAL,  RobotResultMsg::CONFLICT,
                                RobotResultMsg::UNREACHABLE};
  int errors = 0;
  const RobotResultMsg* first = nullptr;
  for (std::uint8_t kind : order) {
    for (const auto& r : robots) {
      if (r.status != kind) continue;
      ++errors;
      if (first == nullptr) first = &r;
    }
  }
  if (errors == 0) return false;
  std::uint8_t status = fleetStatusFor(first->status);
  if (first->status == RobotResultMsg::CONFLICT) {
    status = first->message.find("start overlaps") != std::string::npos ? Response::INVALID_START
                                                                         : Response::INVALID_GOAL;
  }
  std::string message = first->message;
  if (errors > 1) message += " (and " + std::to_string(errors - 1) + " more robot errors, see robots)";
  fail(call, status, message);
  for (auto& r : robots) {
    if (r.status == RobotResultMsg::OK) {
      r.status = RobotResultMsg::NOT_PLANNED;
      r.message = "not planned: " + fleetStatusName(status);
    }
  }
  return true;
}

void markNotPlanned(PlanCall& call) {
  for (auto& r : call.response.robots) {
    if (r.status == RobotResultMsg::OK) r.status = RobotResultMsg::NOT_PLANNED, r.message = "not planned: " + call.response.message;
  }
}

std::uint8_t responseStatus(SolveStatus status) {
  switch (status) {
    case SolveStatus::Success: return Response::SUCCESS;
    case SolveStatus::Timeout:
    case SolveStatus::Cancelled: return Response::TIMEOUT;
    case SolveStatus::Infeasible: return Response::INFEASIBLE;
    case SolveStatus::InvalidInput: return Response::INVALID_REQUEST;
    case SolveStatus::ResourceLimit: return Response::RESOURCE_LIMIT;
    case SolveStatus::InternalError: return Response::INTERNAL_ERROR;
  }
  return Response::INTERNAL_ERROR;
}

void fillResponse(const Instance& instance, const GridMap& grid, const PlanningResult& result,
                  double seconds_per_step, bool cancelled, PlanCall& call) {
  Response& res = call.response;
  const int n = static_cast<int>(instance.robots.size());
  res.statistics.decomposition_time = result.decompose_s;
  res.statistics.solve_time = result.solve_s;
  int largest = 0;
  for (int s = 0; s < static_cast<int>(result.subproblems.size()); ++s) {
    const SolvedSubproblem& sub = result.subproblems[s];
    fleet_planner::SubproblemInfo info;
    info.index = s;
    info.cluster = sub.cluster;
    info.level = sub.level;
    for (int r : sub.robots) {
      info.robot_ids.push_back(instance.robots[r].id);
      for (auto& placement : call.placements) {
        if (placement.robot_id == instance.robots[r].id) placement.subproblem = s;
      }
    }
    info.status = statusName(sub.status);
    info.solve_time = sub.time_s;
    info.delay = sub.delay;
    info.lower_bound = sub.stats.lower_bound;
    info.stopped_early = sub.stopped_early;
    largest = std::max(largest, static_cast<int>(sub.robots.size()));
    res.subproblems.push_back(std::move(info));
  }
  res.statistics.subproblems = static_cast<std::uint32_t>(result.subproblems.size());
  res.statistics.largest_subproblem = largest;
  res.statistics.lattice_step = static_cast<std::uint32_t>(result.lattice_step);

  if (!result.success()) {
    std::string message = std::string(statusName(result.status)) + ": " + result.reason;
    if (cancelled) message = "cancelled (the node is shutting down): " + result.reason;
    for (const std::string& aside : result.step_asides) message += "; " + aside;
    for (const std::string& merge : result.merges) message += "; " + merge;
    fail(call, responseStatus(result.status), message);
    for (auto& r : res.robots) r.status = RobotResultMsg::NOT_PLANNED, r.message = "not planned: " + message;
    return;
  }

  const double dt = seconds_per_step;
  for (int i = 0; i < n; ++i) {
    fleet_planner::RobotTimeline timeline = robotTimeline(instance.robots[i], result.plan.paths[i], grid, dt);
    for (const auto& placement : call.placements) {
      if (placement.robot_id == timeline.robot_id) timeline.subproblem = placement.subproblem;
    }
    res.timelines.push_back(std::move(timeline));
    res.robots[i].message = "planned: cost " + std::to_string(res.timelines.back().cost) + " steps";
  }
  res.statistics.soc = result.metrics.soc;
  res.statistics.makespan = result.metrics.makespan;
  res.status = Response::SUCCESS;
  res.message = "planned " + std::to_string(n) + " robots with " + result.backend +
                (result.layered ? " (layered, " : " (raw, ") +
                std::to_string(result.subproblems.size()) + " subproblems, lattice step " +
                std::to_string(result.lattice_step) + "): SOC " + std::to_string(result.metrics.soc) +
                ", makespan " + std::to_string(result.metrics.makespan) + " steps";
}

std::string fleetStatusName(std::uint8_t status) {
  static const char* const kNames[] = {"SUCCESS",         "TIMEOUT",       "INFEASIBLE",    "INVALID_REQUEST",
                                       "NO_MAP",          "UNKNOWN_ROBOT", "UNKNOWN_BACKEND", "INVALID_START",
                                       "INVALID_GOAL",    "NO_TRANSFORM",  "BUSY",          "INTERNAL_ERROR",
                                       "RESOURCE_LIMIT"};
  return status < std::size(kNames) ? kNames[status] : "STATUS_" + std::to_string(status);
}

std::string robotStatusName(std::uint8_t status) {
  static const char* const kNames[] = {"OK",           "UNKNOWN_ROBOT", "INVALID_START", "INVALID_GOAL",
                                       "NO_TRANSFORM", "UNREACHABLE",   "CONFLICT",      "NOT_PLANNED",
                                       "INVALID_FOOTPRINT"};
  return status < std::size(kNames) ? kNames[status] : "STATUS_" + std::to_string(status);
}

}  // namespace fleet_planner
