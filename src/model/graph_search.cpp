#include "fleet_planner/model/graph_search.h"

#include <cstdlib>
#include <functional>
#include <queue>
#include <tuple>

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

int stepsBound(const StateGraph& graph, const GridPose& from, const GridPose& to) {
  const int step = graph.actionModel().step;
  const int cells = std::abs(from.x - to.x) + std::abs(from.y - to.y);
  return (cells + step - 1) / step + (from.heading != to.heading ? 1 : 0);
}

int stepsBetween(const StateGraph& graph, StateId from, StateId to, long long max_expansions, long long& expansions) {
  return WaySearch(graph).steps(from, to, max_expansions, expansions);
}

int WaySearch::steps(StateId from, StateId to, long long max_expansions, long long& expansions) {
  if (!graph_.valid(from) || !graph_.valid(to)) return -1;
  if (cost_.empty()) cost_.assign(static_cast<std::size_t>(graph_.stateIdCount()), -1);
  for (StateId s : touched_) cost_[s] = -1;
  touched_.clear();
  const GridPose goal = graph_.pose(to);
  auto h = [&](StateId s) { return stepsBound(graph_, graph_.pose(s), goal); };
  auto set = [&](StateId s, int g) {
    if (cost_[s] < 0) touched_.push_back(s);
    cost_[s] = g;
  };
  set(from, 0);
  // (f, -g, state): among equal f the deepest first, which crosses a plateau of equal f along
  // one way instead of all of it; then by state id (deterministic).
  using Entry = std::tuple<int, int, StateId>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  open.push({h(from), 0, from});
  const long long limit = expansions + max_expansions;
  while (!open.empty() && expansions < limit) {
    const auto [f, minus_g, s] = open.top();
    open.pop();
    const int g = cost_[s];
    if (-minus_g > g) continue;  // superseded
    if (s == to) return g;
    ++expansions;
    graph_.forEachSuccessor(s, [&](Action, StateId next) {
      if (cost_[next] >= 0 && cost_[next] <= g + 1) return;
      set(next, g + 1);
      open.push({g + 1 + h(next), -(g + 1), next});
    });
  }
  return -1;
}

}  // namespace fleet_planner
