#pragma once
/// LA-LaCAM: LaCAM for large agents.
///   Okumura. "LaCAM: Search-Based Algorithm for Quick Multi-Agent Pathfinding." AAAI 2023.
///   Okumura et al. "Priority Inheritance with Backtracking for Iterative Multi-agent Path
///   Finding." IJCAI 2019 (PIBT, the successor generator).
///   Layered LA-MAPF paper, "Solving and combining" and "Application": the parallel backend.
///
/// High level: depth-first search over joint configurations; each node lazily grows a tree of
/// constraints (which agent goes where next), and every constraint yields at most one successor
/// configuration from the generator, so the search is complete: INFEASIBLE only once every
/// configuration reachable has been exhausted. Successor generator (see la_pibt.h): agents in
/// priority order take the best next state, by exact distance to their target, whose swept
/// cells overlap neither the sweeps already taken nor the footprints of agents still to move.
/// Static footprints of other subproblems are obstacles; timed paths are not supported.
/// A search that fills its memory budget restarts with a seed derived from the given one, until
/// the deadline; INFEASIBLE is only returned when the first search exhausted the space.
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

struct LaLacamOptions {
  /// Memory budget of one search; a search that fills it restarts with a derived seed.
  double max_memory_mb = 512;
  /// Chance that a revisited configuration sends the search back to the start configuration.
  double restart_rate = 0.1;
};

class LaLacam : public Solver {
 public:
  explicit LaLacam(LaLacamOptions options = {}) : options_(options) {}
  std::string name() const override { return "la_lacam"; }
  bool avoidsMovingObstacles() const override { return false; }
  /// Options by name (backend_options.cpp): the fields of the options struct above.
  void configure(const BackendOptionValues& values) override;
  SolveResult solve(const Subproblem& problem) override;

 private:
  LaLacamOptions options_;
};

}  // namespace fleet_planner
