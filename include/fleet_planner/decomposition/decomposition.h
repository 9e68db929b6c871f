#pragma once
/// Decomposition of an LA-MAPF instance into subproblems (paper: Methodology). Clusters have no
/// solving order (Algorithms 1-2); each cluster is split into levels, which do (Algorithms 3-4).
/// The result is one ordered list of subproblems: solving them one after another, each treating
/// the others as static obstacles (earlier ones at their targets, later ones at their starts),
/// loses no solvability.
#include <string>
#include <utility>
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/instance.h"

namespace fleet_planner {

/// Which steps to run: 1 = initial clusters, 2 = cluster bipartition, 3 = initial levels,
/// 4 = level bipartition. Steps run in order up to `last_step` (1..4).
struct DecompositionOptions {
  int last_step = 4;
  int threads = 1;  ///< for the per-robot relation graphs; the result does not depend on it
  /// Step 4 also peels off, one by one, robots that can go before or after all the others of
  /// their level (beyond the paper; legal by the same conditions). False: Algorithm 4 alone.
  bool peel_levels = true;
};

struct DecompositionSubproblem {
  std::vector<int> robots;  ///< instance indices, ascending
  int cluster = 0;          ///< index of the cluster it belongs to
  int level = 0;            ///< position among its cluster's levels (0 = first)
};

struct DecompositionStep {
  int step = 0;             ///< 1..4
  int subproblems = 0;      ///< after the step
  int largest = 0;          ///< robots in the largest subproblem after the step
  double time_s = 0.0;      ///< time of this step alone
};

struct Decomposition {
  std::vector<DecompositionSubproblem> subproblems;  ///< in solving order
  std::vector<DecompositionStep> steps;              ///< statistics after each step run
  double relations_s = 0.0;                          ///< building the relation graphs
  double entangled_s = 0.0;                          ///< finding the entangled pairs
  /// False if the deadline cut it short: then the result is that of the steps completed, which
  /// is still legal. Step 1 always runs once the relation graphs are built; if the deadline
  /// passes while they are built, the result is the whole fleet as one subproblem (no steps).
  bool complete = true;
  /// Pairs of robots (instance indices, a < b) of one subproblem that the relation graphs do not
  /// let go one after the other in either order, even alone on the map (beyond the paper). A
  /// pair of two subproblems always can (legality), and so can a subproblem's other pairs: two
  /// robots that cannot both reach their targets are one of these pairs. The relations are
  /// conservative, so a few of these pairs can be ordered after all. Ascending by subproblem,
  /// then by robot. Left out once the deadline has passed: `pairs_complete` is false then.
  std::vector<std::pair<int, int>> entangled_pairs;
  bool pairs_complete = true;

  int largest() const;
  /// Largest subproblem / robots (the paper's decomposition rate); 0 for no robots.
  double rate(int robots) const;
};

/// Decomposes `instance`. Every robot's target must be reachable from its start in its graph
/// (throws InvalidInput naming the robot otherwise). Deterministic.
Decomposition decompose(const Instance& instance, const FleetGraphs& graphs, const DecompositionOptions& options,
                        const Deadline& deadline = {});

}  // namespace fleet_planner
