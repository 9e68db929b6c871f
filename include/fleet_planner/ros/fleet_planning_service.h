#pragma once
/// The PlanFleet service's logic, without a ROS master: request -> checks -> core instance ->
/// Layered LA-MAPF -> response. The node owns one, feeds it the map and the footprint registry,
/// and forwards the calls; gtest drives it directly.
///
/// Every outcome is a status in the response, never an exception: bad requests, unknown robots,
/// poses off the map or in collision, timeouts and internal errors alike (rule: a service call
/// always answers).
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <fleet_planner/FleetFootprints.h>
#include <fleet_planner/PlanFleet.h>

#include "fleet_planner/planning/graph_cache.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"
#include "fleet_planner/ros/planner_config.h"

namespace fleet_planner {

/// A map as received, never modified after: a call keeps its snapshot while a new map arrives.
struct MapSnapshot {
  GridMap grid;
  std::uint64_t version = 0;  ///< increases with every map message
};

/// A robot of a call as placed on the map: for markers and playback.
struct RobotPlacement {
  std::string robot_id;
  fleet_planner::RobotFootprint footprint;  ///< metres
  geometry_msgs::Pose2D start, goal;        ///< snapped to the grid
  int subproblem = -1;
};

/// What a successful plan gives the execution: the core instance and plan, and the map.
struct ExecutablePlan {
  std::shared_ptr<const GridMap> map;
  Instance instance;
  Plan plan;
  int lattice_step = 1;
  bool allow_backward = false;  ///< the plan may move robots backward
  /// The state graphs the plan was made on (its lattice): re-planning reuses them.
  std::shared_ptr<const FleetGraphs> graphs;
  /// Per robot, per state: the map-frame pose (the timelines' states: true start and goal yaws).
  std::vector<std::vector<geometry_msgs::Pose2D>> poses;
};

/// A call's response plus what the markers and the execution need.
struct PlanCall {
  fleet_planner::PlanFleet::Response response;
  std::vector<RobotPlacement> placements;  ///< robots whose start and goal are valid
  std::shared_ptr<const MapSnapshot> map;  ///< the map the call planned on (null: none)
  std::shared_ptr<const ExecutablePlan> executable;  ///< on SUCCESS: the plan to execute
};

/// Looks up a robot's current pose in the map frame (TF); false with a reason if it cannot.
using StartLookup = std::function<bool(const std::string& robot_id, geometry_msgs::Pose2D& pose, std::string& error)>;

class FleetPlanningService {
 public:
  explicit FleetPlanningService(PlannerConfig config) : config_(std::move(config)) {}

  /// Thread-safe; a running call keeps the map it started with. Throws InvalidInput for a bad
  /// map and ResourceLimitError, before converting it, for one over max_map_cells (the previous
  /// map stays; without one, calls answer RESOURCE_LIMIT).
  void setMap(const nav_msgs::OccupancyGrid& grid);
  /// Thread-safe; replaces the whole registry.
  void setFootprints(const fleet_planner::FleetFootprints& fleet);
  bool hasMap() const;

  using Clock = std::chrono::steady_clock;

  /// The checks that need neither the map nor the registry: the task list, robot ids, pose
  /// values (NaN, inf, |theta| > kMaxAbsYaw), time_limit (<= max_time_limit), decomposition,
  /// steps, backend. Returns the answer to a bad request (as plan() would give it), nothing for a
  /// good one. Cheap and lock-free: the node answers a bad request at once, even while another
  /// call plans. Never throws.
  std::optional<fleet_planner::PlanFleet::Response> checkRequest(const fleet_planner::PlanFleet::Request& request) const;
  /// Seconds the request may take: its time_limit, or the configured one for -1. Meaningful once
  /// checkRequest() passed.
  double timeLimit(const fleet_planner::PlanFleet::Request& request) const;

  /// Plans one request. Never throws. `lookup` serves tasks with start_from_tf; `cancel` (may be
  /// null) stops the planning early (answered TIMEOUT, "cancelled"). The time limit counts from
  /// `received` (the node passes the time it took the call up, so waiting for the planner counts).
  PlanCall plan(const fleet_planner::PlanFleet::Request& request, const StartLookup& lookup,
                const std::atomic<bool>* cancel = nullptr, Clock::time_point received = Clock::now());

  const PlannerConfig& config() const { return config_; }

 private:
  /// checkRequest()'s checks: false with the answer in `call` for a bad request; otherwise the
  /// resolved time limit and backend name.
  bool checkFields(const fleet_planner::PlanFleet::Request& request, PlanCall& call, double& time_limit,
                   std::string& backend) const;
  void planChecked(const fleet_planner::PlanFleet::Request& request, const StartLookup& lookup,
                   const std::atomic<bool>* cancel, Clock::time_point received, PlanCall& call);

  const PlannerConfig config_;
  mutable std::mutex mutex_;  ///< guards map_ and footprints_
  std::shared_ptr<const MapSnapshot> map_;
  std::uint64_t map_version_ = 0;
  std::string map_refused_;  ///< why the last map was refused (max_map_cells); empty once one is taken
  std::map<std::string, fleet_planner::RobotFootprint> footprints_;
  GraphCache graphs_;  ///< the last call's state graphs, reused for the same map and footprints
};

/// "SUCCESS", "TIMEOUT", ... for a PlanFleet response status ("STATUS_<n>" if unknown).
std::string fleetStatusName(std::uint8_t status);
/// "OK", "UNKNOWN_ROBOT", ... for a RobotResult status.
std::string robotStatusName(std::uint8_t status);

}  // namespace fleet_planner
