// Proving a pair of robots infeasible; see infeasible_pairs.h.
#include "fleet_planner/infeasibility/infeasible_pairs.h"

#include <algorithm>

#include "fleet_planner/infeasibility/pair_goal_search.h"
#include "fleet_planner/solvers/lacam/la_lacam.h"
#include "fleet_planner/solvers/search/safe_interval_search.h"
#include "fleet_planner/solvers/search/solve_common.h"

namespace fleet_planner {

namespace {

// The same for its first, short try: a pair whose targets leave it few configurations to reach
// them from is decided by it at once, where the forward search may spend its whole budget
// before failing.
constexpr long long kFirstBackwardConfigurations = 20'000;
// Expansions of each single-robot search of a pair planned in turn: a robot's way across a
// real map, around one other robot, takes a few thousand.
constexpr long long kInTurnExpansions = 20'000;

Subproblem pairOf(const Subproblem& around, int a, int b, const Deadline& deadline) {
  Subproblem pair;
  pair.instance = around.instance;
  pair.graphs = around.graphs;
  pair.robots = {a, b};
  pair.blocked = around.blocked;
  pair.returning = around.returning;
  pair.deadline = deadline;
  return pair;
}

}  // namespace

SolveResult searchPairAlone(const Subproblem& around, int a, int b, long long max_expansions, const Deadline& deadline) {
  Subproblem pair = pairOf(around, a, b, deadline);
  pair.max_expansions = max_expansions;
  return LaLacam().solve(pair);
}

SolveResult planPairInTurn(const Subproblem& around, int a, int b, long long max_expansions_per_search,
                           const Deadline& deadline) {
  return solveWith(pairOf(around, a, b, deadline), false, [&](const SearchSpace& space, SolveStats& stats) {
    for (const auto& [first, second] : {std::pair{0, 1}, std::pair{1, 0}}) {
      SoftPathTable table(space);
      std::vector<StatePath> paths(2);
      for (int k : {first, second}) {
        const SafeIntervalResult r = safeIntervalSearch(space, k, table, deadline, max_expansions_per_search);
        stats.low_level_expansions += r.expansions;
        if (r.outcome != SafeIntervalResult::Outcome::Found) break;
        paths[k] = r.path;
        table.insert(k, paths[k]);
      }
      if (paths[second].empty() || firstConflict(space, paths)) continue;
      SolveResult found;
      found.status = SolveStatus::Success;
      found.paths = toPosePaths(space, paths);
      return found;
    }
    return failedResult(SolveStatus::Timeout, "neither robot can go first");
  });
}

PairDecision decidePair(const Instance& instance, const FleetGraphs& graphs, int a, int b, long long max_expansions,
                        const Deadline& deadline, long long backward_configurations) {
  Subproblem alone;  // the map's obstacles only
  alone.instance = &instance;
  alone.graphs = &graphs;
  if (planPairInTurn(alone, a, b, kInTurnExpansions, deadline).success()) return {PairVerdict::Possible, ""};
  const PairEnds ends_a{a, instance.robots[a].start, instance.robots[a].target};
  const PairEnds ends_b{b, instance.robots[b].start, instance.robots[b].target};
  auto backwards = [&](long long configurations) {
    return searchPairBackwards(graphs, ends_a, ends_b, configurations, deadline);
  };
  auto unreachable = [](const PairSearch& back) {
    return "every configuration from which both can reach their targets explored, " +
           std::to_string(back.configurations) + " of them: their starts are not one";
  };
  const PairSearch first = backwards(std::min(kFirstBackwardConfigurations, backward_configurations));
  if (first.reach == PairReach::Reachable) return {PairVerdict::Possible, ""};
  if (first.reach == PairReach::Unreachable) return {PairVerdict::Impossible, unreachable(first)};
  const SolveResult r = searchPairAlone(alone, a, b, max_expansions, deadline);
  if (r.status == SolveStatus::Infeasible) return {PairVerdict::Impossible, r.reason};
  if (r.success()) return {PairVerdict::Possible, ""};
  // Forwards from the start the space was too large; backwards from the goal it may not be.
  const PairSearch back = backwards(backward_configurations);
  if (back.reach == PairReach::Unreachable) return {PairVerdict::Impossible, unreachable(back)};
  if (back.reach == PairReach::Reachable) return {PairVerdict::Possible, ""};
  return {PairVerdict::Undecided, deadline.expired() ? "the deadline passed"
                                                     : "neither decided within " + std::to_string(max_expansions) +
                                                           " expansions forwards nor " +
                                                           std::to_string(backward_configurations) +
                                                           " configurations backwards"};
}

std::optional<std::string> findInfeasiblePair(const Instance& instance, const FleetGraphs& graphs,
                                              const std::vector<std::pair<int, int>>& pairs,
                                              long long max_expansions, const Deadline& deadline) {
  for (const auto& [a, b] : pairs) {
    if (deadline.expired()) return std::nullopt;
    const PairDecision d = decidePair(instance, graphs, a, b, max_expansions, deadline);
    if (d.verdict != PairVerdict::Impossible) continue;
    return "robots '" + instance.robots[a].id + "' and '" + instance.robots[b].id +
           "' cannot both reach their targets, even alone on the map (" + d.why + ")";
  }
  return std::nullopt;
}

}  // namespace fleet_planner
