#include "fleet_planner/model/graph_search.h"

namespace fleet_planner {

std::vector<std::int32_t> distancesTo(const StateGraph& graph, StateId target) {
  std::vector<std::int32_t> dist(graph.stateIdCount(), -1);
  if (!graph.valid(target)) return dist;
  std::vector<StateId> queue{target};
  dist[target] = 0;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const StateId s = queue[head];
    graph.forEachPredecessor(s, [&](Action, StateId prev) {
      if (dist[prev] < 0) {
        dist[prev] = dist[s] + 1;
        queue.push_back(prev);
      }
    });
  }
  return dist;
}

std::vector<StateId> reachableFrom(const StateGraph& graph, StateId start) {
  if (!graph.valid(start)) return {};
  std::vector<std::uint8_t> seen(graph.stateIdCount(), 0);
  std::vector<StateId> queue{start};
  seen[start] = 1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    graph.forEachSuccessor(queue[head], [&](Action, StateId next) {
      if (!seen[next]) {
        seen[next] = 1;
        queue.push_back(next);
      }
    });
  }
  return queue;
}

bool isReachable(const StateGraph& graph, StateId from, StateId to) {
  if (!graph.valid(from) || !graph.valid(to)) return false;
  if (from == to) return true;
  std::vector<std::uint8_t> seen(graph.stateIdCount(), 0);
  std::vector<StateId> queue{from};
  seen[from] = 1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    bool found = false;
    graph.forEachSuccessor(queue[head], [&](Action, StateId next) {
      if (next == to) found = true;
      if (!seen[next]) {
        seen[next] = 1;
        queue.push_back(next);
      }
    });
    if (found) return true;
  }
  return false;
}

}  // namespace fleet_planner
