#pragma once
// Benchmark problems for the microbenchmarks: the shared benchmark maps and pools, found in
// $FLEET_PLANNER_BENCHMARK or else in FLEET_PLANNER_BENCHMARK_DIR (set by CMake to
// ../shared/benchmark next to the source folder). Loaded once per (map, K) and cached.
#include <memory>
#include <string>

#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner::bench {

struct Problem {
  GridMap map;
  Instance instance;  ///< the pool's "K mixed" robots, or a generated fleet
  std::unique_ptr<FleetGraphs> graphs;  ///< built on first use by graphs()
  const FleetGraphs& fleetGraphs();
};

/// The folder holding maps/ and instances/.
std::string benchmarkDir();

/// Map `name` with the "K mixed" robots of its pool; nullptr (and `error` set) if the files are
/// missing or unreadable, so that the benchmark can skip with that message.
Problem* problem(const std::string& name, int k, std::string& error);

/// Map `name` with `robots` robots of the paper's distribution (generateInstance with `seed`,
/// the CLI's `generate`), cached like problem().
Problem* generatedProblem(const std::string& name, int robots, unsigned seed, std::string& error);

/// Every robot of `p` as one subproblem (raw), seed 1, a 600 s deadline and `budget` low-level
/// expansions (-1: none), so that every machine does the same work.
Subproblem wholeFleet(Problem& p, long long budget);

}  // namespace fleet_planner::bench
