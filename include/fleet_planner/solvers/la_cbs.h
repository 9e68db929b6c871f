#pragma once
/// LA-CBS: Conflict-Based Search for large agents.
///   Sharon, Stern, Felner, Sturtevant. "Conflict-based search for optimal multi-agent
///   pathfinding." Artificial Intelligence 219, 2015.
///   Li, Surynek, Felner, Ma, Kumar, Koenig. "Multi-Agent Path Finding for Large Agents."
///   AAAI 2019 (geometric vertex and transfer conflicts, constraints on the agent's own states).
///   Layered LA-MAPF paper, "Solving and combining": the serial backend, which plans around the
///   timed paths of earlier subproblems.
///
/// High level: best-first over the constraint tree by sum of costs, fewer conflicts first;
/// branches on the earliest conflict: a cell both agents cover is forbidden to one agent or the
/// other at that time (vertex conflict) or during that step (transfer conflict), which splits
/// soundly because any two poses covering one cell conflict. Bypass (Boyarski et
/// al. 2015) adopts a child's path instead of branching when it costs the same and conflicts
/// less. Low level: space-time A* with the exact distance heuristic, tie-broken by conflicts
/// with the other agents' paths. Optimal sum of costs when it succeeds.
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

struct LaCbsOptions {
  bool bypass = true;
  long long max_low_level_nodes = 4'000'000;  ///< per low-level call
  double max_memory_mb = 2048;                ///< constraint tree paths; beyond: TIMEOUT
};

class LaCbs : public Solver {
 public:
  explicit LaCbs(LaCbsOptions options = {}) : options_(options) {}
  std::string name() const override { return "la_cbs"; }
  bool avoidsMovingObstacles() const override { return true; }
  SolveResult solve(const Subproblem& problem) override;

 private:
  LaCbsOptions options_;
};

}  // namespace fleet_planner
