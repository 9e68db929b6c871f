#pragma once
/// The planner node's one typed configuration: defaults here, loaded from the parameter server in
/// one place (loadPlannerConfig), checked by one function (checkPlannerConfig).
/// config/planner.yaml documents every parameter.
#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "fleet_planner/runtime/resource_limits.h"
#include "fleet_planner/planning/planning_options.h"
#include "fleet_planner/ros/conversions.h"

namespace fleet_planner {

struct PlannerConfig {
  // Planning.
  std::string backend = "la_lns";    ///< default backend: "la_lns", "la_lacam", "la_cbs" or any plugin name
  double time_limit = 10.0;          ///< default seconds per call, graphs included
  /// Largest time_limit a request may ask for (a larger one, or inf, is INVALID_REQUEST): no
  /// call can hold the planner for longer. time_limit must not exceed it.
  double max_time_limit = 60.0;
  bool decomposition = true;         ///< default: Layered LA-MAPF (false: raw)
  int decomposition_steps = 4;       ///< default last decomposition step, 1..4
  int threads = 0;                   ///< threads for graphs and subproblems; 0: the machine's cores
  /// Backend tried on a subproblem that the backend fails, before the safeguard merges it
  /// (LayeredOptions::fallback); "" for none.
  std::string fallback = "la_lns";
  /// The planning lattice's step in metres (rounded to map cells, at least 1); 0: the fleet's
  /// default (a third of the narrowest robot's width). See planning/lattice.h.
  double lattice_resolution = 0.0;
  /// Robots may also move backward one lattice step (ActionModel::allow_backward). Real robots
  /// reverse; without it a robot facing a wall or another robot with no room to turn is stuck.
  bool allow_backward = true;
  /// Options of the backends by name: {backend: {option: value}} (backend_parameters.h).
  BackendParameters backend_parameters;
  bool refine = true;                ///< replan delayed robots after merging (plan_refinement.h)
  bool compress = true;              ///< drop the waits no conflict needs (plan_compression.h)
  bool cell_steps = true;            ///< a lattice plan on steps of one cell (cell_steps.h)
  std::string busy_policy = "reject";  ///< a call while another plans: "reject" (BUSY) or "queue"

  // Resource limits (core/resource_limits.h): beyond them a call answers RESOURCE_LIMIT.
  int max_map_cells = 16'000'000;  ///< larger maps are refused when they arrive
  int max_robots = 1000;           ///< tasks per call
  double max_memory_mb = 4096;     ///< the node's resident memory while planning, MB

  // Map and poses.
  int occupied_threshold = 65;   ///< occupancy values >= this are obstacles (1..100)
  std::string unknown_policy = "obstacle";  ///< unknown cells (-1): "obstacle" or "free"
  double position_tolerance = 0.1;  ///< metres a pose may be from its cell centre
  double heading_tolerance = 0.2;   ///< radians within which a yaw counts as a grid heading
  /// Cells a rotation may clip beyond its end poses, 0..0.25 (Footprint::sweep_tolerance);
  /// 0 is the exact sweep.
  double sweep_tolerance = 0.0;

  // Time and frames.
  double seconds_per_step = 0.5;      ///< duration of one plan step (a move or a quarter turn)
  std::string map_frame = "map";
  std::string base_frame = "base_link";  ///< robot frames are <robot_id>/<base_frame>
  double tf_timeout = 0.5;               ///< seconds to wait for a robot's transform

  // Playback of the last plan as TF frames <robot_id>/<planned_frame>.
  bool playback = true;
  std::string planned_frame = "planned";
  double playback_rate = 1.0;  ///< 2.0 plays twice as fast
  bool playback_loop = true;   ///< start over after the makespan (with a pause)

  // Execution of the last plan by the robots (their poses from TF): releases, progress, overlaps.
  bool execute = false;
  double execution_rate = 10.0;       ///< Hz: poses read, releases and ~execution published
  double progress_tolerance = 0.05;   ///< metres from a state's pose for the robot to count as there
  double progress_heading_tolerance = 0.2;  ///< radians, likewise
  double blocked_timeout = 10.0;      ///< seconds waiting for another robot before BLOCKED
  double late_warning = 5.0;          ///< seconds behind the plan before the diagnostics warn
  double off_path_tolerance = 0.3;    ///< metres from its path before a robot is OFF_PATH
  bool replan_blocked = true;         ///< re-plan a BLOCKED robot around the robot it waits for
  bool replan_off_path = true;        ///< re-plan an OFF_PATH robot from where it stands
  double replan_time_limit = 1.0;     ///< seconds for one re-plan (the node's execution waits meanwhile)

  OccupancyPolicy occupancyPolicy() const { return {occupied_threshold, unknown_policy == "free"}; }
  PoseTolerance poseTolerance() const { return {position_tolerance, heading_tolerance}; }
  ResourceLimits resourceLimits() const { return {max_map_cells, max_robots, max_memory_mb}; }
};

/// The planning options of a call with this configuration's defaults (the request may override
/// backend, decomposition, steps, time limit and seed).
PlanningOptions planningOptions(const PlannerConfig& config);

/// Every parameter the node reads, in config/planner.yaml's order (docs/ros.md lists the same).
const std::vector<std::string>& plannerParameterNames();

/// Every problem with the configuration, one line each, naming the parameter ("time_limit must be
/// > 0 (got -1)"); empty when it is usable.
std::vector<std::string> checkPlannerConfig(const PlannerConfig& config);

/// The configuration's backends against the registered ones (once the plugins are loaded): every
/// problem with `backend`, `fallback` (unknown, ambiguous, or parallel for a serial backend) and
/// `backend_parameters` (unknown backend or option, value out of range), one line each, naming
/// the parameter. Empty when a call can use them.
std::vector<std::string> checkPlannerBackends(const PlannerConfig& config);

/// Reads the parameters of `nh` (the node's private handle) over the defaults. Throws InvalidInput
/// naming the parameter for one of the wrong type; values are not range-checked here.
PlannerConfig loadPlannerConfig(const ros::NodeHandle& nh);

/// Parameters under `nh`'s namespace that the planner does not know (typos such as
/// "time_limt"), as full names; the node warns about them.
std::vector<std::string> unknownPlannerParameters(const ros::NodeHandle& nh);

}  // namespace fleet_planner
