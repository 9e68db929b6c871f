#pragma once
/// The one way in: plans a fleet on a map with PlanningOptions. The node, the CLI and the stress
/// tool call this and nothing below it. It owns what every call needs in the same order:
///   memory guard and deadline (from PlanningCall::started) -> the lattice (lattice.h) -> state
///   graphs (cached) -> connections to the lattice -> solvability pre-check -> Layered LA-MAPF
///   or raw (layered_planner.h: decomposition, solving, merging, refinement, compression) ->
///   the connections off the lattice -> the independent validator, on the map's cells.
/// Outcomes are values (status and reason); only bad options (InvalidInput) and a fleet whose
/// graphs exceed the limits before any search (ResourceLimitError) throw.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fleet_planner/layered/layered_planner.h"
#include "fleet_planner/model/instance_check.h"
#include "fleet_planner/planning/graph_cache.h"
#include "fleet_planner/planning/planning_options.h"

namespace fleet_planner {

/// What a call brings besides the problem and the options.
struct PlanningCall {
  /// The time limit counts from here (a node passes when the request arrived).
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
  const std::atomic<bool>* cancel = nullptr;  ///< set: the call stops early, CANCELLED
  GraphCache* cache = nullptr;                ///< null: the graphs are built for this call alone
  std::uint64_t map_version = 0;              ///< the cache's key with the footprints
};

struct PlanningResult : LayeredResult {
  std::string backend;   ///< as used
  std::string fallback;  ///< as used ("" for none)
  int threads = 1;       ///< as used
  bool layered = true;   ///< as used: decomposed (false: raw)
  int lattice_step = 1;  ///< the lattice the plan was made on (cells)
  /// Cells a move of the returned plan advances at most: 1 when it is on cell steps
  /// (PlanningOptions::cell_steps, cell_steps.h), else lattice_step. SOC and makespan count its steps.
  int plan_step = 1;
  long long cell_steps_saved = 0;  ///< steps the retiming on cell steps took off the paths
  double cell_steps_s = 0.0;       ///< putting the plan on cell steps, retiming and checking it
  /// Why each lattice tried before the one used was given up ("step 4: robot 'a' cannot reach
  /// ..."), or, after a time-out on the default lattice, what the lattice twice as coarse did.
  std::vector<std::string> lattice_notes;
  /// The pre-check's per-robot problems (unreachable target, start or target overlaps): the
  /// status is INFEASIBLE when there are any, and nothing was planned.
  SolvabilityReport precheck;
  double precompute_s = 0.0;   ///< building the state graphs (0 when cached)
  bool graphs_cached = false;
  /// On success: the state graphs the plan was made on (its lattice), for re-planning during its
  /// execution (execution/replanning.h).
  std::shared_ptr<const FleetGraphs> graphs;
  double time_s = 0.0;         ///< the whole call, from PlanningCall::started
};

/// Plans `instance` on `map`. A plan returned with SUCCESS has passed the validator; a plan
/// that fails it is INTERNAL_ERROR. Throws InvalidInput listing every problem of `options`
/// (checkPlanningOptions), ResourceLimitError for graphs that would not fit in
/// options.limits.max_memory_mb.
PlanningResult planFleet(const GridMap& map, const Instance& instance, const PlanningOptions& options,
                         const PlanningCall& call = {});

}  // namespace fleet_planner
