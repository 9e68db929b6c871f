// Proving a pair of robots infeasible; see infeasible_pairs.h.
#include "fleet_planner/layered/infeasible_pairs.h"

#include "fleet_planner/solvers/la_lacam.h"

namespace fleet_planner {

std::optional<std::string> findInfeasiblePair(const Instance& instance, const FleetGraphs& graphs,
                                              const std::vector<std::pair<int, int>>& pairs,
                                              long long max_expansions, const Deadline& deadline) {
  for (const auto& [a, b] : pairs) {
    if (deadline.expired()) return std::nullopt;
    Subproblem pair;
    pair.instance = &instance;
    pair.graphs = &graphs;
    pair.robots = {a, b};
    pair.deadline = deadline;
    pair.max_expansions = max_expansions;
    const SolveResult r = LaLacam().solve(pair);
    if (r.status != SolveStatus::Infeasible) continue;
    return "robots '" + instance.robots[a].id + "' and '" + instance.robots[b].id +
           "' cannot both reach their targets, even alone on the map (" + r.reason + ")";
  }
  return std::nullopt;
}

}  // namespace fleet_planner
