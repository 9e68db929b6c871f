#pragma once
/// The options of one planning call, with the package's defaults in one place: the node's
/// parameters (config/planner.yaml) and the CLI's flags map onto these fields, and a field that
/// neither sets keeps the value here. Configuration that caches depend on (the map, the
/// footprints) is not here: it is the call's input.
#include <cstdint>
#include <string>
#include <vector>

#include "fleet_planner/layered/time_budget.h"
#include "fleet_planner/model/action.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/runtime/resource_limits.h"
#include "fleet_planner/solvers/backend_parameters.h"

namespace fleet_planner {

struct PlanningOptions {
  /// Backend of every subproblem: "la_lns", "la_lacam", "la_cbs" or any registered name.
  /// LA-LNS plans each level around the moving robots of the earlier ones, so levels need not
  /// wait for each other; a parallel backend's levels are delayed until they fit.
  std::string backend = "la_lns";
  /// Backend tried on a subproblem that `backend` fails without proving it infeasible, in the
  /// rest of its time share, before the safeguard merges it ("": none). A parallel fallback of a
  /// serial backend plans the level with the earlier levels of its chain at their targets and
  /// delays it until it fits among their paths, as the serial backends do past their budget.
  std::string fallback = "la_lns";
  /// Options of the backends by name, e.g. {"la_lns": {"neighborhood_size": 12}}.
  BackendParameters backend_parameters;
  bool decompose = true;  ///< Layered LA-MAPF; false: the whole fleet as one subproblem (raw)
  int last_step = 4;      ///< decomposition steps 1..4 (clusters, bipartition, levels, bipartition)
  /// Threads for state graphs, relation graphs and subproblems; 0: the machine's cores. The plan
  /// does not depend on it.
  int threads = 0;
  /// Serial backends: plan clusters independently and merge them by delays (false: one chain,
  /// every level around all earlier paths).
  bool independent_clusters = true;
  bool refine = true;    ///< replan robots one at a time around the others after merging
  bool compress = true;  ///< drop every wait that no conflict needs
  /// A plan made on a lattice of step s > 1 is returned on steps of one cell (cell_steps.h): s
  /// steps for each lattice move, so a step lasts the same whatever the lattice, retimed with
  /// `compress`. false: returned on the lattice's steps (a move of s cells in one step).
  bool cell_steps = true;
  std::uint64_t seed = 0;
  /// Seconds for the whole call, state graphs included, counted from PlanningCall::started.
  double time_limit = 10.0;
  /// max_memory_mb bounds the call's resident memory (graphs refused, searches stopped:
  /// RESOURCE_LIMIT); the map and robot limits are checked by the loaders and the node.
  ResourceLimits limits;
  /// The planning lattice's step in map cells (lattice.h): moves advance this many cells. 0: the
  /// default for the fleet (defaultLatticeStep: 1 for the paper's benchmark robots). A fleet that
  /// cannot be planned on it (a robot that cannot reach its target on it, connections that
  /// collide, a lattice plan proven impossible) is planned again on a lattice of half the step,
  /// down to 1 (every such step is reported). On the default of a step above 1, a fleet that
  /// times out within TimeBudget::default_lattice_share of the time is planned in the rest on a
  /// lattice twice as coarse (plan_fleet.cpp).
  int lattice_step = 0;
  /// The action model; its `step` is set from lattice_step.
  ActionModel model;
  /// How the deadline is divided between the stages (time_budget.h).
  TimeBudget budget;
};

/// Every problem with `options`, one line each, naming the option ("fallback: unknown backend
/// 'la_lsn' (known: ...)"): unknown backends, a parallel fallback for a serial backend, backend
/// parameters that do not configure their backend, values out of range. Empty when usable.
std::vector<std::string> checkPlanningOptions(const PlanningOptions& options);

/// The lattice step a call starts with: options.lattice_step, or the fleet's default for 0.
int initialLatticeStep(const PlanningOptions& options, const Instance& instance);

/// `options.threads`, or the machine's cores (at least 1) for 0.
int effectiveThreads(const PlanningOptions& options);

}  // namespace fleet_planner
