#pragma once
/// Helpers shared by the CLI's subcommands.
#include <chrono>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_commands.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/planning/planning_options.h"
#include "fleet_planner/runtime/resource_limits.h"

namespace fleet_planner::cli {

/// Threads to use by default: the machine's cores (at least 1).
int defaultThreads();

/// The process's peak resident set size in MB (VmHWM), or -1 where /proc is missing.
double peakRssMb();

/// Options naming a problem: a map, an instance (benchmark pool or YAML scenario) and how many
/// robots of it to use.
struct ProblemOptions {
  std::string map;       ///< MovingAI .map or map_server .yaml; empty: the scenario's map
  std::string instance;  ///< benchmark .txt or scenario .yaml
  std::string fleet;     ///< the node's inputs instead: a fleet file (the footprint registry's) ...
  std::string tasks;     ///< ... and a tasks file (the demo client's), with --map
  int agents = 0;        ///< 0: every robot; K: the "K mixed" robots of the pool
  bool unknown_is_free = false;
  double sweep_tolerance = 0.0;  ///< set on every robot's footprint (Footprint::sweep_tolerance)
  ResourceLimits limits;  ///< max_map_cells and max_robots are checked by loadProblem
};

/// Registers --map, --instance (or --fleet and --tasks), --agents, --unknown-free and
/// --sweep-tolerance on `cmd`.
void addProblemOptions(CLI::App* cmd, ProblemOptions& options);

/// Registers --max-map-cells, --max-robots and --max-memory-mb on `cmd` (resource_limits.h).
void addLimitOptions(CLI::App* cmd, ResourceLimits& limits);

/// Registers --backend, --fallback and --backend-param (into `params`, applied by
/// applyBackendOptions) on `cmd`, with `options`' values as the defaults.
void addBackendOptions(CLI::App* cmd, PlanningOptions& options, std::vector<std::string>& params);

/// Parses the --backend-param values into options.backend_parameters and turns a fallback of
/// "none" into "" (throws InvalidInput naming a malformed value).
void applyBackendOptions(PlanningOptions& options, const std::vector<std::string>& params);

struct Problem {
  GridMap map;
  Instance instance;
  /// The map is a map_server map (a real map; the node's inputs), not a MovingAI benchmark map.
  bool map_server = false;
};

/// Loads map and instance, picks the robots and validates them against the map (throws
/// InputError with file, line or robot on bad input, ResourceLimitError for a map or fleet over
/// options.limits).
Problem loadProblem(const ProblemOptions& options);

/// Prints one JSON object on one line to stdout.
void printJsonLine(const nlohmann::json& j);

/// Seconds since `start`.
inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace fleet_planner::cli
