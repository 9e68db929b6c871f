#pragma once
/// Layered LA-MAPF (paper: Algorithm 6): decompose the instance into ordered subproblems, solve
/// them one after another with a backend, merge, and validate.
///
/// Serial backends (LA-CBS) plan each subproblem around the timed paths of the earlier ones and
/// the start footprints of the later ones. Parallel backends (LA-LaCAM) plan around the target
/// footprints of earlier subproblems and the start footprints of later ones; their paths are
/// then delayed at their starts until they fit among the earlier paths (Algorithm 5). Each
/// subproblem gets a share of the remaining time (at least a quarter, more for a larger part of
/// the robots left; the last one all of it). If a subproblem fails, or its share runs out, while
/// time remains, it is merged with a neighbour and the merged one is solved again (the merges
/// are reported). The merged plan is then compressed (waits that no conflict needs are dropped)
/// and always passes the validator.
#include <string>
#include <vector>

#include "fleet_planner/core/deadline.h"
#include "fleet_planner/core/fleet_graphs.h"
#include "fleet_planner/core/grid_map.h"
#include "fleet_planner/core/instance.h"
#include "fleet_planner/core/plan.h"
#include "fleet_planner/decomposition/decomposition.h"
#include "fleet_planner/layered/plan_compression.h"
#include "fleet_planner/layered/plan_refinement.h"
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

struct LayeredOptions {
  std::string backend = "la_cbs";
  bool decompose = true;  ///< false: the whole fleet as one subproblem (raw)
  int last_step = 4;      ///< decomposition steps 1..4
  int threads = 1;        ///< relation graphs
  bool refine = true;     ///< replan robots one at a time around the others (plan_refinement.h)
  bool compress = true;   ///< drop every wait that no conflict needs (plan_compression.h)
  std::uint64_t seed = 0;
};

struct SolvedSubproblem {
  std::vector<int> robots;  ///< instance indices
  int cluster = 0;
  int level = 0;
  SolveStatus status = SolveStatus::Success;
  std::string reason;
  double time_s = 0.0;
  int delay = 0;  ///< steps its paths were delayed by the merge (parallel backends)
  SolveStats stats;  ///< the backend's statistics for its last attempt
};

struct LayeredResult {
  SolveStatus status = SolveStatus::InvalidInput;
  std::string reason;
  Plan plan;  ///< on success: one path per robot, instance order, validated
  PlanMetrics metrics;
  Decomposition decomposition;               ///< as computed (before any merge)
  std::vector<SolvedSubproblem> subproblems;  ///< as solved, in order
  std::vector<std::string> merges;            ///< one line per safeguard merge
  RefinementStats refinement;                 ///< of the merged plan
  CompressionStats compression;               ///< of the refined plan
  double decompose_s = 0.0;
  double solve_s = 0.0;
  bool success() const { return status == SolveStatus::Success; }
};

/// Plans the instance. `graphs` must be the instance's graphs on `map`. Throws InvalidInput for
/// an unknown backend or bad options; planning outcomes are in the result.
LayeredResult planLayered(const GridMap& map, const Instance& instance, const FleetGraphs& graphs,
                          const LayeredOptions& options, const Deadline& deadline);

}  // namespace fleet_planner
