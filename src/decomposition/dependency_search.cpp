#include "fleet_planner/decomposition/dependency_search.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>

namespace fleet_planner {

namespace {

// Every SAT of component c passes the filter, the robot's own start and target aside.
bool passable(const RelationGraph& r, const SatFilter& filter, int c) {
  const ComponentGraph& g = *r.graph;
  for (int k = g.sat_begin[c]; k < g.sat_begin[c + 1]; ++k) {
    const int s = g.sats[k];
    if (s / 2 != r.robot && !filter.passes(s)) return false;
  }
  return true;
}

// The SATs (ascending, the robot's own left out) of the components on the path that `parent`
// links from r.target back to r.start (parent -1).
std::vector<int> pathSats(const RelationGraph& r, const std::vector<int>& parent) {
  const ComponentGraph& g = *r.graph;
  std::vector<int> sats;
  for (int c = r.target; c >= 0; c = parent[c]) {
    for (int k = g.sat_begin[c]; k < g.sat_begin[c + 1]; ++k) {
      if (g.sats[k] / 2 != r.robot) sats.push_back(g.sats[k]);
    }
  }
  std::sort(sats.begin(), sats.end());
  sats.erase(std::unique(sats.begin(), sats.end()), sats.end());
  return sats;
}

}  // namespace

bool pathExists(const RelationGraph& r, const SatFilter& filter, std::vector<int>* witness) {
  if (r.start < 0 || r.target < 0 || !passable(r, filter, r.start) || !passable(r, filter, r.target)) return false;
  const ComponentGraph& g = *r.graph;
  // Depth-first; a component is judged once, when first reached.
  std::vector<int> parent(static_cast<std::size_t>(g.numComponents()), -2);  // -2: unseen
  std::vector<int> stack{r.start};
  parent[r.start] = -1;
  bool found = r.start == r.target;
  while (!found && !stack.empty()) {
    const int c = stack.back();
    stack.pop_back();
    for (int k = g.edge_begin[c]; k < g.edge_begin[c + 1]; ++k) {
      const int next = g.edges[k];
      if (parent[next] != -2) continue;
      parent[next] = c;
      if (!passable(r, filter, next)) continue;
      if (next == r.target) {
        found = true;
        break;
      }
      stack.push_back(next);
    }
  }
  if (found && witness) *witness = pathSats(r, parent);
  return found;
}

std::optional<std::vector<int>> searchPathSats(const RelationGraph& r, const SatFilter& filter) {
  const ComponentGraph& g = *r.graph;
  const int n = g.numComponents();
  auto passable = [&](int c) { return fleet_planner::passable(r, filter, c); };
  auto cost = [&](int c) {
    int k = 0;
    for (int i = g.sat_begin[c]; i < g.sat_begin[c + 1]; ++i) k += g.sats[i] / 2 != r.robot;
    return k;
  };
  // Entering `next` from `c` costs the SATs `next` has that `c` has not: a path that stays near
  // one SAT across several components pays for it once (an approximation of counting distinct
  // SATs, which no shortest-path label can do exactly).
  auto stepCost = [&](int c, int next) {
    int k = 0;
    int i = g.sat_begin[c];
    for (int j = g.sat_begin[next]; j < g.sat_begin[next + 1]; ++j) {
      const int s = g.sats[j];
      while (i < g.sat_begin[c + 1] && g.sats[i] < s) ++i;
      const bool shared = i < g.sat_begin[c + 1] && g.sats[i] == s;
      k += !shared && s / 2 != r.robot;
    }
    return k;
  };
  if (r.start < 0 || r.target < 0 || !passable(r.start) || !passable(r.target)) return std::nullopt;
  constexpr int kInf = std::numeric_limits<int>::max();
  std::vector<int> dist(n, kInf), parent(n, -1);
  using Item = std::pair<int, int>;  // (distance, component): ties by component, deterministic
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  dist[r.start] = cost(r.start);
  open.push({dist[r.start], r.start});
  while (!open.empty()) {
    const auto [d, c] = open.top();
    open.pop();
    if (d != dist[c]) continue;
    if (c == r.target) break;
    for (int k = g.edge_begin[c]; k < g.edge_begin[c + 1]; ++k) {
      const int next = g.edges[k];
      const int nd = d + stepCost(c, next);
      if (dist[next] != kInf && dist[next] <= nd) continue;
      if (!passable(next)) continue;
      dist[next] = nd;
      parent[next] = c;
      open.push({dist[next], next});
    }
  }
  if (dist[r.target] == kInf) return std::nullopt;
  return pathSats(r, parent);
}

}  // namespace fleet_planner
