// Orders of the parking plan's turns; see parking_orders.h.
#include "fleet_planner/solvers/lns/parking_orders.h"

#include <algorithm>
#include <cmath>

#include "fleet_planner/model/collision.h"

namespace fleet_planner {

namespace {

// A bound on how far from its pose a cell of agent a's footprint can be, in cells.
int footprintReach(const SearchSpace& space, int a) {
  return static_cast<int>(std::ceil(std::sqrt(static_cast<double>(space.cells(a).maxNormSq())))) + 1;
}

}  // namespace

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

std::vector<int> targetsCrossed(const SearchSpace& space, const std::vector<StatePath>& ways) {
  const int n = space.numAgents();
  std::vector<int> crossed(n, 0);
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      if (b == a) continue;
      const GridPose target = space.graph(b).pose(space.target(b));
      const int reach = footprintReach(space, a) + footprintReach(space, b);
      for (StateId s : ways[a]) {
        const GridPose q = space.graph(a).pose(s);
        // Footprints farther apart than their reaches cannot overlap: skip the cell test.
        if (fartherApart(q, target, reach)) continue;
        if (footprintsOverlap(space.cells(b), target, space.cells(a), q)) {
          ++crossed[b];
          break;
        }
      }
    }
  }
  return crossed;
}

std::vector<std::vector<int>> parkingOrders(const SearchSpace& space, const std::vector<int>& longest_first,
                                            int count) {
  std::vector<std::vector<int>> orders = {longest_first};
  auto add = [&](std::vector<int> order) {
    if (std::find(orders.begin(), orders.end(), order) == orders.end()) orders.push_back(std::move(order));
  };
  auto way = [&](int a) { return space.distance(a, space.start(a)); };
  if (count >= 2) {
    std::vector<int> shortest_first = longest_first;
    std::stable_sort(shortest_first.begin(), shortest_first.end(),
                     [&](int x, int y) { return way(x) < way(y); });
    add(std::move(shortest_first));
  }
  if (count >= 3) {
    std::vector<StatePath> ways(space.numAgents());
    for (int a = 0; a < space.numAgents(); ++a) ways[a] = shortestWay(space, a);
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
