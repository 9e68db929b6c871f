// Pairs of a subproblem that no order of the two serves; see Decomposition::entangled_pairs.
#include "dependency_oracle.h"

namespace fleet_planner::detail {

namespace {

// Whether robot a can go to its target first, robot b standing at its start, and b after it,
// a standing at its target: a's path keeps clear of b's start footprint and b's path of a's
// target footprint (relation_graph.h: a path through unrelated states keeps clear of the SAT).
bool canGoFirst(DependencyOracle& oracle, int a, int b) {
  Mask avoid(2 * oracle.robots(), 0);
  avoid[2 * b] = 1;
  if (!oracle.satPathExists(a, {}, avoid)) return false;
  avoid[2 * b] = 0;
  avoid[2 * a + 1] = 1;
  return oracle.satPathExists(b, {}, avoid);
}

}  // namespace

std::vector<std::pair<int, int>> entangledPairs(DependencyOracle& oracle, const std::vector<int>& robots,
                                                const Deadline& deadline) {
  std::vector<std::pair<int, int>> out;
  for (std::size_t x = 0; x < robots.size(); ++x) {
    if (deadline.expired()) break;
    for (std::size_t y = x + 1; y < robots.size(); ++y) {
      const int a = std::min(robots[x], robots[y]), b = std::max(robots[x], robots[y]);
      if (!canGoFirst(oracle, a, b) && !canGoFirst(oracle, b, a)) out.push_back({a, b});
    }
  }
  return out;
}

}  // namespace fleet_planner::detail
