#include "fleet_planner/solvers/cbs/path_around_others.h"

#include <algorithm>

#include "fleet_planner/solvers/cbs/cbs_split.h"
#include "fleet_planner/solvers/search/agent_conflicts.h"
#include "fleet_planner/solvers/search/agent_constraints.h"

namespace fleet_planner {

LowLevelResult pathAroundOthers(const SearchSpace& space, int a, const std::vector<StatePath>& paths,
                                const Deadline& deadline, long long max_nodes) {
  // The others' motions step by step (CBS's conflict-avoidance table): a step of a whose sweep
  // meets one of theirs is a vertex or transfer conflict of the validator, and is not taken.
  const ConflictAvoidanceTable others(space, paths, a);
  int horizon = 0;
  for (const StatePath& p : paths) horizon = std::max(horizon, static_cast<int>(p.size()) - 1);
  // a holds its target for good only after the last step at which somebody passes over it.
  AgentConstraints constraints;
  const StateId target = space.target(a);
  for (int t = horizon; t >= 0; --t) {
    if (others.conflicts(target, Action::Wait, t) == 0) continue;
    if (t == horizon) return {};  // somebody parks on it
    constraints.requireCostAbove(t);
    break;
  }
  LowLevelOptions o;
  o.max_nodes = max_nodes;
  o.blocked = [&others](StateId s, Action act, int t) { return others.conflicts(s, act, t) > 0; };
  o.blocked_until = horizon;
  return spaceTimeAStar(space, a, constraints, deadline, o);
}

std::vector<StatePath> aroundOthersInTurn(const SearchSpace& space, std::vector<StatePath> paths,
                                          const Deadline& deadline, long long max_nodes, long long& expansions) {
  for (;;) {
    const std::vector<std::pair<int, int>> pairs = conflictingPairs(space, paths);
    if (pairs.empty()) return paths;
    StatePath best;
    int best_agent = -1;
    for (const int a : {pairs[0].first, pairs[0].second}) {
      LowLevelResult r = pathAroundOthers(space, a, paths, deadline, max_nodes);
      expansions += r.expansions;
      if (r.outcome != LowLevelResult::Outcome::Found) continue;
      if (best_agent < 0 || pathCost(r.path) - pathCost(paths[a]) < pathCost(best) - pathCost(paths[best_agent])) {
        best = std::move(r.path);
        best_agent = a;
      }
    }
    if (best_agent < 0) return {};
    paths[best_agent] = std::move(best);
  }
}

}  // namespace fleet_planner
