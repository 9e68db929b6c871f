// Orders of the parking plan's turns; see parking_orders.h.
#include "fleet_planner/solvers/lns/parking_orders.h"

#include <algorithm>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/solvers/lns/parking_precedence.h"

namespace fleet_planner {

StatePath shortestWay(const SearchSpace& space, int a) {
  StateId s = space.start(a);
  int d = space.distance(a, s);
  if (d < 0) return {};
  StatePath way = {s};
  const StateGraph& g = space.graph(a);
  while (d > 0) {
    StateId down = kNoState;
    g.forEachSuccessor(s, [&](Action action, StateId t) {
      if (down == kNoState && space.allows(a, s, action) && space.distance(a, t) == d - 1) down = t;
    });
    if (down == kNoState) return {};  // not a distance table of this graph: no way
    way.push_back(s = down);
    --d;
  }
  return way;
}

bool wayCoversTarget(const SearchSpace& space, int a, const StatePath& way, int b) {
  const GridPose target = space.graph(b).pose(space.target(b));
  const int reach = space.cells(a).reach() + space.cells(b).reach();
  return std::any_of(way.begin(), way.end(), [&](StateId s) {
    const GridPose q = space.graph(a).pose(s);
    // Footprints farther apart than their reaches cannot overlap: skip the cell test.
    return !fartherApart(q, target, reach) && footprintsOverlap(space.cells(b), target, space.cells(a), q);
  });
}

std::vector<int> targetsCrossed(const SearchSpace& space, const std::vector<StatePath>& ways) {
  const int n = space.numAgents();
  std::vector<int> crossed(n, 0);
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      if (b != a && wayCoversTarget(space, a, ways[a], b)) ++crossed[b];
    }
  }
  return crossed;
}

std::vector<std::vector<int>> parkingOrders(const SearchSpace& space, const std::vector<int>& longest_first,
                                            int count, long long precedence_expansions) {
  const int n = space.numAgents();
  std::vector<StatePath> ways;
  if (precedence_expansions > 0 || count >= 3) {
    ways.resize(n);
    for (int a = 0; a < n; ++a) ways[a] = shortestWay(space, a);
  }
  std::vector<std::vector<int>> orders;
  auto add = [&](std::vector<int> order) {
    if (std::find(orders.begin(), orders.end(), order) == orders.end()) orders.push_back(std::move(order));
  };
  // The first order with the robots that shut others in or out after them; the second as it
  // is, so that where both get every robot home the faster plan is still there to keep.
  if (precedence_expansions > 0) {
    add(honourPrecedence(longest_first, parkingPrecedence(space, ways, precedence_expansions)));
  } else {
    add(longest_first);
  }
  auto way = [&](int a) { return space.distance(a, space.start(a)); };
  if (count >= 2) {
    std::vector<int> shortest_first = longest_first;
    std::stable_sort(shortest_first.begin(), shortest_first.end(),
                     [&](int x, int y) { return way(x) < way(y); });
    add(std::move(shortest_first));
  }
  if (count >= 3) {
    const std::vector<int> crossed = targetsCrossed(space, ways);
    std::vector<int> crossed_last = longest_first;
    std::stable_sort(crossed_last.begin(), crossed_last.end(), [&](int x, int y) {
      return crossed[x] != crossed[y] ? crossed[x] < crossed[y] : way(x) < way(y);
    });
    add(std::move(crossed_last));
  }
  return orders;
}

}  // namespace fleet_planner
