#include "fleet_planner/solvers/lns/joint_repair.h"

#include <algorithm>

#include "fleet_planner/solvers/cbs/la_cbs.h"
#include "fleet_planner/solvers/search/solve_common.h"

namespace fleet_planner {

std::vector<StatePath> jointRepair(const SearchSpace& space, const Subproblem& problem,
                                   const SoftPathTable& table, const std::vector<int>& group,
                                   double seconds, long long max_expansions, std::uint64_t seed,
                                   long long& expansions) {
  Subproblem sub;
  sub.instance = problem.instance;
  sub.graphs = problem.graphs;
  sub.blocked = problem.blocked;
  sub.moving = problem.moving;
  sub.returning = problem.returning;
  for (int a : group) sub.robots.push_back(space.robot(a));
  for (int b = 0; b < space.numAgents(); ++b) {
    if (!table.contains(b) || std::find(group.begin(), group.end(), b) != group.end()) continue;
    MovingObstacle m;
    m.robot = space.robot(b);
    for (StateId s : table.path(b)) m.path.push_back(space.graph(b).pose(s));
    sub.moving.push_back(std::move(m));
  }
  sub.deadline = problem.deadline.within(seconds);
  sub.seed = seed;
  sub.max_expansions = max_expansions;
  // Not anytime: the repair wants a conflict-free group plan within its small budget, and the
  // primal step's searches would spend that budget; with them on, the sweep's plans were the
  // same (session 68), so the repair stays the LA-CBS it was.
  LaCbsOptions options;
  options.anytime = false;
  const SolveResult r = LaCbs(options).solve(sub);
  expansions += r.stats.low_level_expansions;
  if (!r.success()) return {};
  return toStatePaths(space, group, r.paths);
}

}  // namespace fleet_planner
