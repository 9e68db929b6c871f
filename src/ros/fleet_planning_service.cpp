#include "fleet_planner/ros/fleet_planning_service.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <set>

#include "fleet_planner/planning/plan_fleet.h"
#include "fleet_planner/ros/backend_loader.h"
#include "fleet_planner/ros/conversions.h"
#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/runtime/resource_limits.h"
#include "plan_response.h"
#include "task_placement.h"

namespace fleet_planner {

namespace {

using Request = fleet_planner::PlanFleet::Request;
using Response = fleet_planner::PlanFleet::Response;
using RobotResultMsg = fleet_planner::RobotResult;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%g", v);
  return buf;
}

std::string quoted(const std::string& id) { return "robot '" + id + "'"; }

}  // namespace

void FleetPlanningService::setMap(const nav_msgs::OccupancyGrid& grid) {
  try {
    checkMapCells(grid.info.width, grid.info.height, config_.resourceLimits(), "map");  // before allocating
  } catch (const ResourceLimitError& e) {
    std::lock_guard<std::mutex> lock(mutex_);
    map_refused_ = e.what();  // calls without an earlier map answer RESOURCE_LIMIT with this
    throw;
  }
  auto snapshot = std::make_shared<MapSnapshot>();
  snapshot->grid = convert(grid, config_.occupancyPolicy());  // throws InvalidInput: keep the old map
  std::lock_guard<std::mutex> lock(mutex_);
  snapshot->version = ++map_version_;
  map_ = std::move(snapshot);
  map_refused_.clear();
}

void FleetPlanningService::setFootprints(const fleet_planner::FleetFootprints& fleet) {
  std::map<std::string, fleet_planner::RobotFootprint> footprints;
  for (const auto& f : fleet.robots) footprints[f.robot_id] = f;
  std::lock_guard<std::mutex> lock(mutex_);
  footprints_ = std::move(footprints);
}

bool FleetPlanningService::hasMap() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return map_ != nullptr;
}

PlanCall FleetPlanningService::plan(const Request& request, const StartLookup& lookup,
                                    const std::atomic<bool>* cancel, Clock::time_point received) {
  PlanCall call;
  call.response.statistics.soc = -1;
  call.response.statistics.makespan = -1;
  try {
    checkRobotCount(static_cast<long long>(request.tasks.size()), config_.resourceLimits());
    planChecked(request, lookup, cancel, received, call);
  } catch (const ResourceLimitError& e) {
    fail(call, Response::RESOURCE_LIMIT, e.what());
    markNotPlanned(call);
  } catch (const DeadlineExpired& e) {  // the state graphs were not done in time
    fail(call, Response::TIMEOUT, std::string("TIMEOUT: ") + e.what());
    markNotPlanned(call);
  } catch (const InputError& e) {
    fail(call, Response::INVALID_REQUEST, e.what());
  } catch (const std::exception& e) {
    fail(call, Response::INTERNAL_ERROR, std::string("internal error: ") + e.what());
  } catch (...) {
    fail(call, Response::INTERNAL_ERROR, "internal error: unknown exception");
  }
  if (call.response.status != Response::SUCCESS) call.response.timelines.clear();
  call.response.statistics.total_time = since(received);
  return call;
}

std::optional<Response> FleetPlanningService::checkRequest(const Request& request) const {
  PlanCall call;
  call.response.statistics.soc = -1;
  call.response.statistics.makespan = -1;
  double time_limit = 0;
  std::string backend;
  try {
    if (checkFields(request, call, time_limit, backend)) return std::nullopt;
  } catch (const std::exception& e) {
    fail(call, Response::INTERNAL_ERROR, std::string("internal error: ") + e.what());
  }
  call.response.statistics.robots = static_cast<std::uint32_t>(request.tasks.size());
  return call.response;
}

double FleetPlanningService::timeLimit(const Request& request) const {
  return request.time_limit == -1.0 ? config_.time_limit : request.time_limit;
}

bool FleetPlanningService::checkFields(const Request& request, PlanCall& call, double& time_limit,
                                       std::string& backend) const {
  const int n = static_cast<int>(request.tasks.size());
  auto reject = [&](std::uint8_t status, const std::string& message) {
    fail(call, status, message);
    return false;
  };
  if (n == 0) return reject(Response::INVALID_REQUEST, "tasks is empty: give one task per robot");
  std::map<std::string, int> task_of;
  for (int i = 0; i < n; ++i) {
    const std::string& id = request.tasks[i].robot_id;
    if (id.empty()) return reject(Response::INVALID_REQUEST, "tasks[" + std::to_string(i) + "]: robot_id is empty");
    const auto [it, fresh] = task_of.emplace(id, i);
    if (!fresh) {
      return reject(Response::INVALID_REQUEST, quoted(id) + " has two tasks (tasks[" + std::to_string(it->second) +
                                                   "] and tasks[" + std::to_string(i) + "])");
    }
  }
  time_limit = timeLimit(request);
  if (request.time_limit != -1.0 && (!(request.time_limit > 0) || !std::isfinite(request.time_limit))) {
    return reject(Response::INVALID_REQUEST,
                  "time_limit must be > 0 seconds, or -1 for the planner's default (" + number(config_.time_limit) +
                      " s); got " + number(request.time_limit));
  }
  if (time_limit > config_.max_time_limit) {
    return reject(Response::INVALID_REQUEST, "time_limit " + number(request.time_limit) +
                                                 " s is above the planner's max_time_limit (" +
                                                 number(config_.max_time_limit) + " s)");
  }
  if (request.decomposition > Request::DECOMPOSITION_RAW) {
    return reject(Response::INVALID_REQUEST,
                  "decomposition must be DECOMPOSITION_DEFAULT (0), _LAYERED (1) or _RAW (2); got " +
                      std::to_string(request.decomposition));
  }
  if (request.steps > 4) {
    return reject(Response::INVALID_REQUEST,
                  "steps must be 1..4, or 0 for the planner's default; got " + std::to_string(request.steps));
  }
  const std::string wanted = request.backend.empty() ? config_.backend : request.backend;
  std::string why_not;
  backend = resolveBackendName(wanted, &why_not);
  if (backend.empty()) return reject(Response::UNKNOWN_BACKEND, why_not);

  // Pose values no map can place (NaN, inf, a yaw that is noise): per robot, as the map checks.
  auto& robots = call.response.robots;
  robots.assign(n, fleet_planner::RobotResult());
  for (int i = 0; i < n; ++i) {
    const auto& task = request.tasks[i];
    robots[i].robot_id = task.robot_id;
    robots[i].status = RobotResultMsg::OK;
    std::string problem;
    if (!task.start_from_tf && !(problem = poseValueProblem(task.start)).empty()) {
      robots[i].status = RobotResultMsg::INVALID_START;
      robots[i].message = quoted(task.robot_id) + ": start " + problem;
    } else if (!(problem = poseValueProblem(task.goal)).empty()) {
      robots[i].status = RobotResultMsg::INVALID_GOAL;
      robots[i].message = quoted(task.robot_id) + ": goal " + problem;
    }
  }
  if (failOnRobotErrors(call)) return false;
  robots.clear();
  return true;
}

void FleetPlanningService::planChecked(const Request& request, const StartLookup& lookup,
                                       const std::atomic<bool>* cancel, Clock::time_point received, PlanCall& call) {
  const auto t0 = received;
  Response& res = call.response;
  const int n = static_cast<int>(request.tasks.size());
  res.statistics.robots = n;

  // The request's own fields.
  double time_limit = 0;
  std::string backend;
  if (!checkFields(request, call, time_limit, backend)) return;

  std::shared_ptr<const MapSnapshot> map;
  std::map<std::string, fleet_planner::RobotFootprint> registry;
  std::string map_refused;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    map = map_;
    registry = footprints_;
    map_refused = map_refused_;
  }
  if (!map && !map_refused.empty()) return fail(call, Response::RESOURCE_LIMIT, "the map was refused: " + map_refused);
  if (!map) return fail(call, Response::NO_MAP, "no map received yet (topic 'map', nav_msgs/OccupancyGrid)");
  call.map = map;
  const GridMap& grid = map->grid;

  // Each robot: footprint, start, goal.
  const std::vector<TaskState> tasks = placeTasks(request, grid, registry, config_, lookup, call);
  if (failOnRobotErrors(call)) return;

  // The core instance, planned by the facade; its pre-check names unreachable goals and overlaps.
  Instance instance;
  for (int i = 0; i < n; ++i) {
    instance.robots.push_back({request.tasks[i].robot_id, tasks[i].footprint, tasks[i].start, tasks[i].goal,
                               "tasks[" + std::to_string(i) + "]", tasks[i].start_yaw, tasks[i].goal_yaw});
  }
  PlanningOptions options = planningOptions(config_);
  options.backend = backend;
  if (!config_.fallback.empty()) {
    std::string why_not;
    options.fallback = resolveBackendName(config_.fallback, &why_not);
    // Checked at startup (checkPlannerBackends): failing here is a defect, not a bad request.
    if (options.fallback.empty()) throw std::logic_error("parameter 'fallback': " + why_not);
  }
  options.decompose = request.decomposition == Request::DECOMPOSITION_DEFAULT ? config_.decomposition
                      : request.decomposition == Request::DECOMPOSITION_LAYERED;
  options.last_step = request.steps == 0 ? config_.decomposition_steps : request.steps;
  options.seed = request.seed;
  options.time_limit = time_limit;
  if (config_.lattice_resolution > 0) {
    options.lattice_step = std::max(1, static_cast<int>(std::lround(config_.lattice_resolution / grid.resolution())));
  }
  options.model.allow_backward = config_.allow_backward;
  PlanningCall planning_call;
  planning_call.started = t0;
  planning_call.cancel = cancel;
  planning_call.cache = &graphs_;
  planning_call.map_version = map->version;
  const PlanningResult result = planFleet(grid, instance, options, planning_call);
  res.statistics.precompute_time = result.precompute_s;
  for (const RobotProblem& p : result.precheck.problems) {
    auto& robot = res.robots[p.robot];
    if (robot.status != RobotResultMsg::OK) continue;
    robot.status = p.kind == RobotProblem::Kind::Unreachable ? RobotResultMsg::UNREACHABLE
                   : p.kind == RobotProblem::Kind::InvalidStart ? RobotResultMsg::INVALID_START
                   : p.kind == RobotProblem::Kind::InvalidTarget ? RobotResultMsg::INVALID_GOAL
                                                                 : RobotResultMsg::CONFLICT;
    robot.message = p.reason;
  }
  if (failOnRobotErrors(call)) return;

  fillResponse(instance, grid, result, config_.seconds_per_step, cancel != nullptr && cancel->load(), call);
  res.statistics.backward_moves = options.model.allow_backward;
  if (res.status == Response::SUCCESS) {
    auto executable = std::make_shared<ExecutablePlan>();
    executable->map = std::shared_ptr<const GridMap>(map, &map->grid);  // shares the snapshot
    executable->instance = instance;
    executable->plan = result.plan;
    executable->lattice_step = result.lattice_step;
    executable->allow_backward = options.model.allow_backward;
    executable->graphs = result.graphs;
    for (const auto& timeline : res.timelines) {
      auto& poses = executable->poses.emplace_back();
      for (const auto& s : timeline.states) {
        geometry_msgs::Pose2D p;
        p.x = s.x, p.y = s.y, p.theta = s.yaw;
        poses.push_back(p);
      }
    }
    call.executable = std::move(executable);
  }
}

}  // namespace fleet_planner
