// Pairwise delay heuristic for LA-CBS; see pairwise_delay.h for the reference.
#include "fleet_planner/solvers/cbs/pairwise_delay.h"

#include <algorithm>
#include <tuple>

namespace fleet_planner {

void PairwiseDelayBound::set(int i, int j, long long bound) {
  if (!known(i, j)) known_pairs_.emplace_back(std::min(i, j), std::max(i, j));
  bound_[index(i, j)] = std::max(bound_[index(i, j)], bound);
}

namespace {

struct Edge {
  int u, v;
  long long delta;
};

// Smallest sum of x over `vertices` with x_u + x_v >= delta on every edge (x >= 0, integer):
// depth-first over the vertices in order, each taking the least value its assigned neighbours
// force or more, up to its largest delta; pruned by the best sum so far. Gives up (returns
// false) after `budget` calls.
bool coverFrom(std::size_t k, const std::vector<int>& vertices, const std::vector<Edge>& edges,
               std::vector<long long>& x, long long sum, long long& best, long long& budget) {
  if (--budget < 0) return false;
  if (sum >= best) return true;
  if (k == vertices.size()) {
    best = sum;
    return true;
  }
  const int v = vertices[k];
  long long least = 0, most = 0;
  for (const Edge& e : edges) {
    if (e.u != v && e.v != v) continue;
    const int w = e.u == v ? e.v : e.u;
    most = std::max(most, e.delta);
    if (x[w] >= 0) least = std::max(least, e.delta - x[w]);
  }
  for (long long value = least; value <= std::max(least, most); ++value) {
    x[v] = value;
    if (!coverFrom(k + 1, vertices, edges, x, sum + value, best, budget)) return false;
  }
  x[v] = -1;
  return true;
}

// A greedy matching, largest deltas first (`edges` sorted so): pairs sharing no agent, whose
// deltas add up to a lower bound on the cover.
long long matching(const std::vector<Edge>& edges, int n) {
  std::vector<bool> used(n, false);
  long long sum = 0;
  for (const Edge& e : edges) {
    if (used[e.u] || used[e.v]) continue;
    used[e.u] = used[e.v] = true;
    sum += e.delta;
  }
  return sum;
}

}  // namespace

long long PairwiseDelayBound::heuristic(const std::vector<int>& costs) const {
  std::vector<Edge> edges;
  for (const auto& [i, j] : known_pairs_) {
    const long long d = bound_[index(i, j)] - costs[i] - costs[j];
    if (d > 0) edges.push_back({i, j, d});
  }
  if (edges.empty()) return 0;
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
    return std::tie(b.delta, a.u, a.v) < std::tie(a.delta, b.u, b.v);  // largest first
  });
  // Connected components of the delta graph, each covered on its own.
  std::vector<int> component(n_, -1);
  int components = 0;
  for (const Edge& seed : edges) {
    if (component[seed.u] >= 0) continue;
    std::vector<int> stack{seed.u};
    component[seed.u] = components;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (const Edge& e : edges) {
        if (e.u != v && e.v != v) continue;
        const int w = e.u == v ? e.v : e.u;
        if (component[w] < 0) {
          component[w] = components;
          stack.push_back(w);
        }
      }
    }
    ++components;
  }
  long long h = 0;
  std::vector<long long> x(n_, -1);
  for (int c = 0; c < components; ++c) {
    std::vector<int> vertices;
    std::vector<Edge> inside;
    for (int v = 0; v < n_; ++v) {
      if (component[v] == c) vertices.push_back(v);
    }
    for (const Edge& e : edges) {
      if (component[e.u] == c) inside.push_back(e);
    }
    if (static_cast<int>(vertices.size()) <= kExactCoverSize) {
      long long best = 0;
      for (const Edge& e : inside) best += e.delta;  // every edge paid in full: a cover
      long long budget = kExactCoverCalls;
      if (coverFrom(0, vertices, inside, x, 0, best, budget)) {
        h += best;
        continue;
      }
      std::fill(x.begin(), x.end(), -1);
    }
    h += matching(inside, n_);
  }
  return h;
}

}  // namespace fleet_planner
