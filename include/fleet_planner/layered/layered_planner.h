#pragma once
/// Layered LA-MAPF (paper: Algorithm 6): decompose the instance into ordered subproblems, solve
/// them with a backend, merge, improve and validate.
///
/// Solving and merging (subproblem_solving.h): serial backends (LA-CBS) plan each level around
/// the timed paths of the earlier levels of its cluster; parallel backends (LA-LaCAM) plan each
/// subproblem around the target footprints of earlier ones; both block the start footprints of
/// later subproblems, and plans are delayed at their starts until they fit (Algorithm 5).
/// Independent work runs on `threads` threads with the same result. If a subproblem fails, or
/// its share of the time runs out, while time remains, it is solved again with the robots
/// standing near its robots' ways free to step aside, then merged with a neighbour and solved
/// again (both are reported). The merged plan is then refined (robots replanned around
/// the others) and compressed (waits that no conflict needs are dropped), and always passes the
/// validator.
#include <string>
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"
#include "fleet_planner/decomposition/decomposition.h"
#include "fleet_planner/layered/plan_compression.h"
#include "fleet_planner/layered/plan_refinement.h"
#include "fleet_planner/layered/subproblem_solving.h"
#include "fleet_planner/layered/time_budget.h"
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

struct LayeredOptions {
  std::string backend = "la_cbs";
  bool decompose = true;  ///< false: the whole fleet as one subproblem (raw)
  int last_step = 4;      ///< decomposition steps 1..4
  int threads = 1;        ///< relation graphs and subproblems; the result does not depend on it
  /// Serial backends: plan clusters independently (in parallel) and merge them by delays, instead
  /// of planning every level around all earlier paths (one chain, the paper's serial scheme).
  bool independent_clusters = true;
  /// Backend tried on a subproblem that `backend` fails, before the safeguard merges it
  /// (subproblem_solving.h); "" for none. It must plan around moving obstacles if `backend` does.
  std::string fallback;
  /// Options of the backends by name (backend_parameters.h); the registry's defaults otherwise.
  BackendParameters backend_parameters;
  /// How the deadline and effort are divided between the stages (time_budget.h).
  TimeBudget budget;
  /// Run the solvability pre-check first (INFEASIBLE naming a robot that cannot reach its
  /// target); the facade (plan_fleet.h) runs it itself and turns it off here.
  bool precheck = true;
  bool refine = true;     ///< replan robots one at a time around the others (plan_refinement.h)
  bool compress = true;   ///< drop every wait that no conflict needs (plan_compression.h)
  std::uint64_t seed = 0;
  /// The caller plans the fleet another way (the planner: on a coarser lattice) if the whole
  /// fleet, solved as one subproblem, stalls: that subproblem ends when its backend stops making
  /// progress (Subproblem::ends_when_stalled) instead of at the deadline.
  bool whole_fleet_ends_when_stalled = false;
};

struct LayeredResult {
  SolveStatus status = SolveStatus::InvalidInput;
  std::string reason;
  Plan plan;  ///< on success: one path per robot, instance order, validated
  PlanMetrics metrics;
  Decomposition decomposition;               ///< as computed (before any merge)
  std::vector<SolvedSubproblem> subproblems;  ///< as solved, in order
  std::vector<std::string> merges;            ///< one line per safeguard merge
  std::vector<std::string> step_asides;       ///< one line per subproblem solved again with robots stepping aside
  RefinementStats refinement;                 ///< of the merged plan
  CompressionStats compression;               ///< of the refined plan
  /// Why the decomposition was set aside and the fleet solved as one subproblem
  /// (TimeBudget::whole_fleet_share); empty when it was not.
  std::string solved_as_one;
  double decompose_s = 0.0;
  double solve_s = 0.0;
  bool success() const { return status == SolveStatus::Success; }
};

/// Plans the instance. `graphs` must be the instance's graphs on `map`. Throws InvalidInput for
/// an unknown backend or bad options; planning outcomes are in the result (a plan that fails
/// the validator is INTERNAL_ERROR). Callers outside the core use planFleet (plan_fleet.h).
LayeredResult planLayered(const GridMap& map, const Instance& instance, const FleetGraphs& graphs,
                          const LayeredOptions& options, const Deadline& deadline);

}  // namespace fleet_planner
