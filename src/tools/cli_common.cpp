#include "cli_common.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/model/instance_check.h"
#include "fleet_planner/io/instance_io.h"
#include "fleet_planner/io/map_io.h"
#include "fleet_planner/io/node_inputs.h"

namespace fleet_planner::cli {

namespace {
int g_exit_code = 0;
}  // namespace

void setExitCode(int code) { g_exit_code = code; }
int exitCode() { return g_exit_code; }

double peakRssMb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  }
  return -1.0;
}

void addProblemOptions(CLI::App* cmd, ProblemOptions& options) {
  cmd->add_option("--map", options.map, "map: MovingAI .map or map_server .yaml (default: the scenario's map)");
  cmd->add_option("--instance", options.instance, "instance: benchmark pool .txt or scenario .yaml");
  cmd->add_option("--fleet", options.fleet,
                  "instead of --instance: the node's fleet file (footprint registry format, metres), with --tasks "
                  "and --map");
  cmd->add_option("--tasks", options.tasks,
                  "instead of --instance: the demo client's tasks file (poses [x, y, yaw] in the map frame, any "
                  "yaw), with --fleet and --map");
  cmd->add_option("--agents", options.agents, "use the 'K mixed' robots of the pool (0 = all)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--unknown-free", options.unknown_is_free, "map_server maps: unknown cells are free");
  cmd->add_option("--sweep-tolerance", options.sweep_tolerance,
                  "cells a rotation may clip beyond its end poses, 0-0.25 (0 = exact sweep; see "
                  "docs/benchmarking.md for the benchmark pools)")
      ->check(CLI::Range(0.0, Footprint::kMaxSweepTolerance));
}

void addLimitOptions(CLI::App* cmd, ResourceLimits& limits) {
  cmd->add_option("--max-map-cells", limits.max_map_cells, "refuse maps of more cells (checked before allocating)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--max-robots", limits.max_robots, "refuse instances of more robots")->check(CLI::PositiveNumber);
  cmd->add_option("--max-memory-mb", limits.max_memory_mb,
                  "resident memory limit: graphs are refused and searches stop (RESOURCE_LIMIT) beyond it")
      ->check(CLI::PositiveNumber);
}

void addBackendOptions(CLI::App* cmd, PlanningOptions& options, std::vector<std::string>& params) {
  cmd->add_option("--backend", options.backend, "la_lns (default) | la_lacam | la_cbs (any registered backend)");
  cmd->add_option("--fallback", options.fallback,
                  "backend tried on a subproblem that --backend fails, in the rest of its time share, before the "
                  "safeguard merges it (default la_lns; none: no fallback)");
  cmd->add_option("--backend-param", params,
                  "a backend's option by name, BACKEND.OPTION=VALUE (repeatable; e.g. la_lns.neighborhood_size=12; "
                  "docs/design.md lists them)");
}

void applyBackendOptions(PlanningOptions& options, const std::vector<std::string>& params) {
  if (options.fallback == "none") options.fallback.clear();
  for (const std::string& p : params) parseBackendParameter(p, options.backend_parameters);
}

Problem loadProblem(const ProblemOptions& options) {
  const bool node_inputs = !options.fleet.empty() || !options.tasks.empty();
  if (node_inputs == !options.instance.empty() || (node_inputs && (options.fleet.empty() || options.tasks.empty()))) {
    throw InvalidInput("give --instance, or --fleet and --tasks (with --map)");
  }
  if (node_inputs) {
    if (options.map.empty()) throw InvalidInput("--fleet and --tasks need --map (a map_server .yaml)");
    MapServerOptions map_options;
    map_options.unknown_is_free = options.unknown_is_free;
    map_options.limits = options.limits;
    GridMap map = loadMap(options.map, map_options);
    Instance instance = loadFleetTasks(map, options.fleet, options.tasks);
    for (Robot& robot : instance.robots) robot.footprint.sweep_tolerance = options.sweep_tolerance;
    checkRobotCount(static_cast<long long>(instance.robots.size()), options.limits);
    return {std::move(map), std::move(instance), true};
  }
  Instance instance = loadInstance(options.instance);
  const std::string map_path = options.map.empty() ? instance.map_file : options.map;
  if (map_path.empty()) {
    throw InvalidInput(options.instance + ": no map given (pass --map or name one in the scenario)");
  }
  MapServerOptions map_options;
  map_options.unknown_is_free = options.unknown_is_free;
  map_options.limits = options.limits;
  GridMap map = loadMap(map_path, map_options);
  if (options.agents > 0) instance = selectMixed(instance, options.agents);
  for (Robot& robot : instance.robots) robot.footprint.sweep_tolerance = options.sweep_tolerance;
  checkRobotCount(static_cast<long long>(instance.robots.size()), options.limits);
  validateInstance(map, instance);
  return {std::move(map), std::move(instance), isMapServerMapPath(map_path)};
}

void printJsonLine(const nlohmann::json& j) { std::cout << j.dump() << std::endl; }

int defaultThreads() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

}  // namespace fleet_planner::cli
