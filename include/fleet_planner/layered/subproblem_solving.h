#pragma once
/// Solving the ordered subproblems of a decomposition and merging their plans (paper:
/// Algorithms 5 and 6), on several threads, with the same result for any number of them.
///
/// What each subproblem sees is fixed before anything is solved, so independent work can run at
/// once:
/// - every subproblem blocks the start footprints of all later subproblems;
/// - a parallel backend (LA-LaCAM) blocks the target footprints of all earlier subproblems;
///   each subproblem is a unit of work, and its plan is delayed at the starts until it fits
///   among the earlier ones (Algorithm 5);
/// - a serial backend (LA-CBS) plans around the timed paths of the earlier subproblems of its
///   own cluster and blocks the targets of earlier subproblems of other clusters. Each cluster
///   (its levels in order) is a unit of work, and its plan is delayed as a whole until it fits
///   among the earlier clusters. Clusters have no solving order and subproblems are listed
///   cluster by cluster, so this is the paper's serial scheme inside a cluster and its parallel
///   scheme between clusters; both keep every subproblem solvable. A level whose search around
///   the timed paths exceeds an expansion budget (deterministic, unlike time) is planned with
///   those robots at their targets instead and delayed until it fits among their paths.
///
/// An instance with two robots that cannot both reach their targets, even alone on the map, has
/// no plan (infeasible_pairs.h): such a pair, found among the decomposition's entangled pairs
/// before solving or among a failed subproblem's pairs, ends the solving with INFEASIBLE.
///
/// Units run on a pool of `threads`. Then the subproblems are merged in order. The first one
/// that failed, while time remains, is solved again with the robots of other subproblems near
/// its robots' ways free to step aside and come back (step_aside.h); if that fails too, it is
/// merged with its neighbour (the next one, or for the last
/// the one before; their clusters become one) and the units it touched are solved again;
/// every merge is reported. With a fallback backend, a subproblem that the backend fails within
/// the first part of its time share is tried with the fallback in the rest before that. Each
/// subproblem's seed is the planner's seed plus its first position in the decomposition, so
/// results do not depend on the threads.
#include <string>
#include <utility>
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"
#include "fleet_planner/layered/time_budget.h"
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

struct SolvedSubproblem {
  std::vector<int> robots;  ///< instance indices
  int cluster = 0;
  int level = 0;
  SolveStatus status = SolveStatus::Success;
  std::string reason;
  double time_s = 0.0;
  int delay = 0;        ///< steps its paths were delayed by the merge (its cluster's, for serial backends)
  int attempts = 0;     ///< times it was solved (more than one after a merge before it)
  SolveStats stats;     ///< the backend's statistics for its last attempt
  std::uint64_t seed_offset = 0;  ///< its first position in the decomposition
  /// Serial backends: planning around its cluster's earlier paths ran past its budget, so the
  /// plan it has (the backend's or the fallback's) was made with their targets blocked and
  /// delayed until it fit among them.
  bool delayed_in_cluster = false;
  /// The backend failed (not INFEASIBLE) within the first part of its time share, and the
  /// fallback backend solved it in the rest.
  bool by_fallback = false;
  /// Its plan is one the backend had in hand when its limit stopped it (LA-CBS's `anytime`; the
  /// fallback's, if any, was not cheaper): where the deadline cut in, not the search's own end.
  bool stopped_early = false;
  /// Robots of other subproblems planned with it, from and back to where they stand, after it
  /// failed with them as obstacles (step_aside.h); their paths follow its robots' in the result.
  std::vector<int> stepping_aside;
  bool step_aside_tried = false;  ///< since its last merge
};

struct SubproblemSolving {
  SolveStatus status = SolveStatus::Success;
  std::string reason;
  std::vector<Path> paths;                 ///< on success: one per robot of the instance
  std::vector<SolvedSubproblem> order;     ///< as solved, in order
  std::vector<std::string> merges;         ///< one line per safeguard merge
  std::vector<std::string> step_asides;    ///< one line per subproblem solved again with robots stepping aside
};

struct SubproblemSolvingOptions {
  std::string backend = "la_cbs";
  /// Backend tried on a subproblem that `backend` fails without proving it infeasible, before
  /// the safeguard merges it ("" or equal to `backend`: none). It must plan around moving
  /// obstacles if `backend` does, and it is tried as `backend` is: around its cluster's earlier
  /// paths within a budget, then with them at their targets and delayed (delayed_in_cluster).
  std::string fallback;
  /// Options of the backends by name (backend_parameters.h).
  BackendParameters backend_parameters;
  /// Time shares, pair proofs, the serial chain's budget, step-aside reach (time_budget.h).
  TimeBudget budget;
  int threads = 1;
  std::uint64_t seed = 0;
  /// The decomposition's entangled pairs (Decomposition::entangled_pairs): the only pairs of
  /// robots that may be unable to both reach their targets. Each is tried for a proof of that
  /// before any subproblem is solved, and a subproblem that fails tries no other pair. Not
  /// `entangled_known` (no decomposition, or one cut short): a failed subproblem tries the pairs
  /// of its robots.
  std::vector<std::pair<int, int>> entangled_pairs;
  bool entangled_known = false;
  /// LayeredOptions::whole_fleet_ends_when_stalled.
  bool whole_fleet_ends_when_stalled = false;
};

/// Solves `order` (robots, cluster and level set; cluster-major order) and merges the plans.
/// Throws InvalidInput for an unknown backend.
SubproblemSolving solveSubproblems(const Instance& instance, const FleetGraphs& graphs,
                                   std::vector<SolvedSubproblem> order, const SubproblemSolvingOptions& options,
                                   const Deadline& deadline);

}  // namespace fleet_planner
