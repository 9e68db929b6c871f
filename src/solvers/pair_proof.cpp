// Two robots alone among static footprints; see pair_proof.h.
#include "fleet_planner/solvers/pair_proof.h"

#include "fleet_planner/solvers/la_lacam.h"

namespace fleet_planner {

SolveResult solvePairAlone(const PairProblem& pair) {
  Subproblem sub;
  sub.instance = pair.instance;
  sub.graphs = pair.graphs;
  sub.robots = {pair.a, pair.b};
  sub.blocked = pair.blocked;
  sub.returning = pair.returning;
  sub.deadline = pair.deadline;
  sub.max_expansions = pair.max_expansions;
  return LaLacam().solve(sub);
}

}  // namespace fleet_planner
