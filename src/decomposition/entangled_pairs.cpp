// Pairs of a subproblem that no order serves; see Decomposition::entangled_pairs.
#include <algorithm>

#include "dependency_oracle.h"

namespace fleet_planner::detail {

namespace {

class PairOrders {
 public:
  PairOrders(DependencyOracle& oracle, const std::vector<int>& robots) : oracle_(oracle) {
    for (int r : robots) {
      // Only the SATs on a robot's best path can be unavoidable: that path avoids all others.
      const auto sats = oracle_.sats(r, {}, {});
      on_path_.push_back(sats ? *sats : std::vector<int>{});
    }
  }

  // Whether the robot at position x of the subproblem can go to its target first, the one at y
  // standing at its start, and y after it, x standing at its target: x's path keeps clear of
  // y's start footprint and y's path of x's target footprint (relation_graph.h: a path through
  // unrelated states keeps clear of the SAT).
  bool canGoFirst(std::size_t x, int a, std::size_t y, int b) {
    return canAvoid(x, a, 2 * b) && canAvoid(y, b, 2 * a + 1);
  }

 private:
  bool canAvoid(std::size_t x, int robot, int sat) {
    const std::vector<int>& path = on_path_[x];
    if (!std::binary_search(path.begin(), path.end(), sat)) return true;
    Mask avoid(2 * oracle_.robots(), 0);
    avoid[sat] = 1;
    return oracle_.satPathExists(robot, {}, avoid);
  }

  DependencyOracle& oracle_;
  std::vector<std::vector<int>> on_path_;  // per position: the SATs of the robot's best path
};

}  // namespace

std::vector<std::pair<int, int>> entangledPairs(DependencyOracle& oracle, const std::vector<int>& robots,
                                                const Deadline& deadline) {
  std::vector<std::pair<int, int>> out;
  if (robots.size() < 2) return out;
  PairOrders orders(oracle, robots);
  for (std::size_t x = 0; x < robots.size(); ++x) {
    if (deadline.expired()) break;
    for (std::size_t y = x + 1; y < robots.size(); ++y) {
      const int a = robots[x], b = robots[y];
      if (!orders.canGoFirst(x, a, y, b) && !orders.canGoFirst(y, b, x, a))
        out.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  return out;
}

}  // namespace fleet_planner::detail
