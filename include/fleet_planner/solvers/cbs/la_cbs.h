#pragma once
/// LA-CBS: Conflict-Based Search for large agents.
///   Sharon, Stern, Felner, Sturtevant. "Conflict-based search for optimal multi-agent
///   pathfinding." Artificial Intelligence 219, 2015.
///   Li, Surynek, Felner, Ma, Kumar, Koenig. "Multi-Agent Path Finding for Large Agents."
///   AAAI 2019 (geometric vertex and transfer conflicts, constraints on the agent's own states).
///   Layered LA-MAPF paper, "Solving and combining": the serial backend, which plans around the
///   timed paths of earlier subproblems.
///
///   Boyarski, Felner, Stern, Sharon, Tolpin, Betzalel, Shimony. "ICBS: Improved Conflict-Based
///   Search Algorithm for Multi-Agent Pathfinding." IJCAI 2015 (conflict prioritisation, bypass).
///   Li, Gange, Harabor, Stuckey, Ma, Koenig. "New Techniques for Pairwise Symmetry Breaking in
///   Multi-Agent Path Finding." ICAPS 2020, Section 5 (target conflicts; cbs_split.h).
///   Li, Felner, Boyarski, Ma, Koenig. "Improved Heuristics for Multi-Agent Path Finding with
///   Conflict-Based Search." IJCAI 2019, Section 4 (WDG; pairwise_delay.h).
///
/// High level: best-first over the constraint tree by f = sum of costs + an admissible pairwise
/// delay heuristic (each conflicting pair of agents is bounded once by a small CBS over the
/// pair), then fewer conflicts, then lower cost. At a node it plans the children of the earliest
/// target conflict of each agent pair (`target_candidates`: one agent already parked on its
/// target, which the pair often reaches only after meeting earlier on the way), then of up to
/// `max_candidate_conflicts` conflicts (the earliest of each agent pair), and branches on the
/// first cardinal one (both children cost more), else semi-cardinal, else the first (ICBS
/// with the children's costs as the classification). A conflict where one agent already holds
/// its target is split on that agent's cost (target reasoning); any other on a cell both agents
/// cover, forbidden to one agent or the other at that time (vertex conflict) or during that step
/// (transfer conflict), which splits soundly because any two poses covering one cell conflict.
/// Bypass adopts a child's path instead of branching when it costs the same and conflicts less.
/// Low level: space-time A* with the exact distance heuristic, tie-broken by conflicts with the
/// other agents' paths. Optimal sum of costs when it succeeds (bounded-suboptimal with
/// `suboptimality` above 1).
///
/// Statistics: high_level_nodes counts the main tree's expansions; low_level_expansions also
/// counts the low-level work of the pair bounds.
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

struct LaCbsOptions {
  bool bypass = true;
  /// Conflicts (the earliest of each agent pair, earliest first) whose splits are planned and
  /// classified before branching; 1 branches on the earliest conflict.
  int max_candidate_conflicts = 4;
  /// Also classify, first, the earliest target conflict of each pair (cbs_split.h), split on the
  /// parked agent's cost, when it is not the pair's earliest conflict.
  bool target_candidates = true;
  /// Constraint-tree nodes each pair bound may expand (see pairwise_delay.h); 0: no heuristic.
  long long pairwise_delay_nodes = 1000;
  /// Low-level expansions the pair bounds may spend beyond those of the tree itself (which they
  /// may match): keeps them from eating the time limit on large maps.
  long long pairwise_delay_expansions = 2'000'000;
  long long max_low_level_nodes = 4'000'000;  ///< per low-level call
  /// Nodes a low-level search may generate while preferring, among equal f, states with fewer
  /// conflicts with the other paths; beyond, it starts over without that preference (deeper
  /// first only). Both find the cheapest path; the preference can make the search expand the
  /// whole conflict-free part of an f-plateau first, millions of nodes on open city maps.
  long long conflict_aware_nodes = 20'000;
  double max_memory_mb = 2048;                ///< constraint tree paths; beyond: TIMEOUT
  /// Constraint-tree expansions before giving up with TIMEOUT (-1: no limit): a budget that,
  /// unlike a time limit, gives the same outcome on every machine.
  long long max_high_level_nodes = -1;
  /// Low-level expansions in all (checked between constraint-tree expansions; -1: no limit).
  long long max_total_expansions = -1;
  /// Above 1: ECBS (Barer, Sharon, Stern, Felner, SoCS 2014) with this weight w. Each low-level
  /// search is focal (fewest conflicts with the other paths among costs within w of the least
  /// possible) and the tree expands, among the nodes costing at most w times the least lower
  /// bound, the one with fewest conflicts. The plan costs at most w times the optimum; the
  /// pairwise delay heuristic bounds the robots' lower bounds instead of their costs. 1: optimal.
  double suboptimality = 1.0;
  /// With suboptimality above 1 or `anytime`, the primal step: where every conflict of the node
  /// being expanded is between the same two agents (first time for that pair), each is planned
  /// around all other paths (path_around_others.h); at weight 1 also, at each node whose
  /// conflicts are of fewer pairs than at any node before, the conflicting agents are planned
  /// around the others in turn. The cheapest such conflict-free plan is returned once it costs
  /// at most the weight times the least lower bound (or at a limit, with `anytime`).
  bool around_others = true;
  /// Stopped by the time limit or a node, expansion or memory limit, the search returns the
  /// cheapest conflict-free plan it has found (by the primal step above) instead of TIMEOUT,
  /// with the reason saying so; SolveStats::lower_bound bounds the optimum from below either
  /// way. A search that ends on its own is unchanged: optimal at weight 1.
  bool anytime = true;
};

class LaCbs : public Solver {
 public:
  explicit LaCbs(LaCbsOptions options = {}) : options_(options) {}
  std::string name() const override { return "la_cbs"; }
  bool avoidsMovingObstacles() const override { return true; }
  /// Options by name (backend_options.cpp): the fields of the options struct above.
  void configure(const BackendOptionValues& values) override;
  SolveResult solve(const Subproblem& problem) override;

 private:
  LaCbsOptions options_;
};

}  // namespace fleet_planner
