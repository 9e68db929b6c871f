#include "fleet_planner/ros/fleet_planning_service.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <set>

#include "fleet_planner/core/errors.h"
#include "fleet_planner/core/footprint_cells.h"
#include "fleet_planner/core/instance_check.h"
#include "fleet_planner/core/memory_guard.h"
#include "fleet_planner/core/resource_limits.h"
#include "fleet_planner/layered_planner.h"
#include "fleet_planner/ros/backend_loader.h"
#include "fleet_planner/ros/conversions.h"

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

/// One task after its checks.
struct TaskState {
  Footprint footprint;  // cells
  GridPose start, goal;
  RobotPlacement placement;
};

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

void fail(PlanCall& call, std::uint8_t status, const std::string& message) {
  call.response.status = status;
  call.response.message = message;
}

/// Marks every robot without an error NOT_PLANNED and sets the fleet status from the robot errors
/// (returns false if there were none).
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

/// Robots still OK after a failure that is not theirs (a limit, the deadline) were not planned.
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
  }
  return Response::INTERNAL_ERROR;
}

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

std::shared_ptr<const FleetGraphs> FleetPlanningService::graphsFor(const MapSnapshot& map,
                                                                   const std::vector<Footprint>& footprints,
                                                                   bool& cached, const Deadline& deadline) {
  std::lock_guard<std::mutex> lock(graphs_mutex_);
  cached = graphs_.graphs && graphs_.map_version == map.version && graphs_.footprints == footprints;
  if (!cached) {
    graphs_.graphs.reset();  // free the old graphs before building new ones
    graphs_.graphs = std::make_shared<const FleetGraphs>(map.grid, footprints, ActionModel{}, config_.threads,
                                                         config_.resourceLimits(), deadline);  // may throw ResourceLimitError
    graphs_.map_version = map.version;
    graphs_.footprints = footprints;
  }
  return graphs_.graphs;
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
  std::vector<TaskState> tasks(n);
  res.robots.resize(n);
  for (int i = 0; i < n; ++i) {
    const auto& task = request.tasks[i];
    auto& result = res.robots[i];
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
      continue;
    }
    std::unique_ptr<FootprintCells> cells;
    try {
      tasks[i].footprint = convert(found->second, grid.resolution());
      tasks[i].footprint.sweep_tolerance = config_.sweep_tolerance;
      const std::string too_large = footprintSizeProblem(tasks[i].footprint, grid);
      if (!too_large.empty()) {
        robotError(RobotResultMsg::INVALID_FOOTPRINT, too_large);
        continue;
      }
      cells = std::make_unique<FootprintCells>(tasks[i].footprint);
    } catch (const InputError& e) {
      result.status = RobotResultMsg::INVALID_FOOTPRINT;
      result.message = e.what();
      continue;
    }
    geometry_msgs::Pose2D start = task.start;
    if (task.start_from_tf) {
      std::string error;
      if (!lookup || !lookup(task.robot_id, start, error)) {
        robotError(RobotResultMsg::NO_TRANSFORM, "start from TF: " + (lookup ? error : "no TF lookup available"));
        continue;
      }
    }
    auto place = [&](const geometry_msgs::Pose2D& pose, const char* what, std::uint8_t status, GridPose& out) {
      const GridPoseFit fit = toGridPose(grid, pose, config_.poseTolerance());
      if (!fit.ok()) {
        robotError(status, std::string(what) + " " + fit.error);
        return false;
      }
      const std::string problem = poseProblem(grid, *cells, fit.pose);
      if (!problem.empty()) {
        robotError(status, std::string(what) + " " + poseText(pose) + " = grid state " + toString(fit.pose) + ": " +
                               problem);
        return false;
      }
      out = fit.pose;
      return true;
    };
    if (!place(start, "start", RobotResultMsg::INVALID_START, tasks[i].start)) continue;
    if (!place(task.goal, "goal", RobotResultMsg::INVALID_GOAL, tasks[i].goal)) continue;
    tasks[i].placement = {task.robot_id, found->second, toPose2D(grid, tasks[i].start), toPose2D(grid, tasks[i].goal), -1};
  }
  for (int i = 0; i < n; ++i) {
    if (res.robots[i].status == RobotResultMsg::OK) call.placements.push_back(tasks[i].placement);
  }
  if (failOnRobotErrors(call)) return;

  // The core instance and its graphs; the pre-check names unreachable goals and overlaps.
  Instance instance;
  std::vector<Footprint> footprints;
  for (int i = 0; i < n; ++i) {
    instance.robots.push_back({request.tasks[i].robot_id, tasks[i].footprint, tasks[i].start, tasks[i].goal,
                               "tasks[" + std::to_string(i) + "]"});
    footprints.push_back(tasks[i].footprint);
  }
  const MemoryGuard memory(config_.max_memory_mb);  // the graphs count against the time limit
  const Deadline deadline = Deadline::in(time_limit - since(t0), cancel).withMemoryGuard(&memory);
  const auto t_graphs = Clock::now();
  bool cached = false;
  const auto graphs = graphsFor(*map, footprints, cached, deadline);
  res.statistics.precompute_time = cached ? 0.0 : since(t_graphs);
  const SolvabilityReport report = checkSolvability(instance, *graphs, deadline);
  for (const RobotProblem& p : report.problems) {
    auto& result = res.robots[p.robot];
    if (result.status != RobotResultMsg::OK) continue;
    result.status = p.kind == RobotProblem::Kind::Unreachable ? RobotResultMsg::UNREACHABLE
                    : p.kind == RobotProblem::Kind::InvalidStart ? RobotResultMsg::INVALID_START
                    : p.kind == RobotProblem::Kind::InvalidTarget ? RobotResultMsg::INVALID_GOAL
                                                                  : RobotResultMsg::CONFLICT;
    result.message = p.reason;
  }
  if (failOnRobotErrors(call)) return;

  // Plan.
  LayeredOptions options;
  options.backend = backend;
  if (!config_.fallback.empty()) {
    std::string why_not;
    options.fallback = resolveBackendName(config_.fallback, &why_not);
    if (options.fallback.empty()) throw InvalidInput("parameter 'fallback': " + why_not);
  }
  options.decompose = request.decomposition == Request::DECOMPOSITION_DEFAULT ? config_.decomposition
                      : request.decomposition == Request::DECOMPOSITION_LAYERED;
  options.last_step = request.steps == 0 ? config_.decomposition_steps : request.steps;
  options.threads = config_.threads;
  options.refine = config_.refine;
  options.compress = config_.compress;
  options.seed = request.seed;
  const LayeredResult result = planLayered(grid, instance, *graphs, options, deadline);

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
    largest = std::max(largest, static_cast<int>(sub.robots.size()));
    res.subproblems.push_back(std::move(info));
  }
  res.statistics.subproblems = static_cast<std::uint32_t>(result.subproblems.size());
  res.statistics.largest_subproblem = largest;

  if (!result.success()) {
    std::string message = std::string(statusName(result.status)) + ": " + result.reason;
    if (deadline.cancelled()) message = "cancelled (the node is shutting down): " + result.reason;
    for (const std::string& aside : result.step_asides) message += "; " + aside;
    for (const std::string& merge : result.merges) message += "; " + merge;
    fail(call, responseStatus(result.status), message);
    for (auto& r : res.robots) r.status = RobotResultMsg::NOT_PLANNED, r.message = "not planned: " + message;
    return;
  }

  const double dt = config_.seconds_per_step;
  for (int i = 0; i < n; ++i) {
    fleet_planner::RobotTimeline timeline;
    timeline.robot_id = instance.robots[i].id;
    const Path& path = result.plan.paths[i];
    timeline.cost = std::max(0, pathCost(path, instance.robots[i].target));
    for (int t = 0; t < static_cast<int>(path.size()); ++t) {
      fleet_planner::TimedState state;
      state.step = t;
      state.time = t * dt;
      const auto pose = toPose2D(grid, path[t]);
      state.x = pose.x, state.y = pose.y, state.yaw = pose.theta;
      state.cell_x = path[t].x, state.cell_y = path[t].y, state.heading = path[t].heading;
      timeline.states.push_back(state);
    }
    for (const auto& placement : call.placements) {
      if (placement.robot_id == timeline.robot_id) timeline.subproblem = placement.subproblem;
    }
    res.timelines.push_back(std::move(timeline));
    res.robots[i].message = "planned: cost " + std::to_string(res.timelines.back().cost) + " steps";
  }
  res.statistics.soc = result.metrics.soc;
  res.statistics.makespan = result.metrics.makespan;
  res.status = Response::SUCCESS;
  res.message = "planned " + std::to_string(n) + " robots with " + backend + (options.decompose ? " (layered, " : " (raw, ") +
                std::to_string(result.subproblems.size()) + " subproblems): SOC " + std::to_string(result.metrics.soc) +
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
