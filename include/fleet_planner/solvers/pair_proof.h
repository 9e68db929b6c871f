#pragma once
/// Whether two robots can reach their targets together with nothing on the map but some static
/// footprints (beyond the paper). Dropping robots or obstacles from a problem only makes it
/// easier, so a pair that cannot proves that every problem with both robots and at least those
/// obstacles has no plan: the subproblem that holds them (LA-LNS, in a knot it cannot untie), or
/// the whole instance (the layered planner, with no obstacles). LA-LaCAM decides the pair: its
/// search over joint configurations is complete, and it ends either with a plan or with every
/// reachable configuration explored.
#include <vector>

#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

struct PairProblem {
  const Instance* instance = nullptr;
  const FleetGraphs* graphs = nullptr;
  int a = -1, b = -1;                      ///< instance indices
  std::vector<StaticFootprint> blocked;    ///< the obstacles kept
  std::vector<StaticFootprint> returning;  ///< a or b planned from and back to this pose
  Deadline deadline;
  long long max_expansions = -1;
};

/// LA-LaCAM's answer for the pair alone: INFEASIBLE is the proof (its reason says why), anything
/// else is none.
SolveResult solvePairAlone(const PairProblem& pair);

}  // namespace fleet_planner
