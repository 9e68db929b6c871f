#pragma once
/// An admissible heuristic for the LA-CBS high level from pairs of agents, in the spirit of the
/// weighted dependency graph of Li, Felner, Boyarski, Ma, Koenig. "Improved Heuristics for
/// Multi-Agent Path Finding with Conflict-Based Search." IJCAI 2019, Section 4 (WDG).
///
/// WDG solves each conflicting pair under the node's constraints; here each pair is bounded
/// once, without constraints: `bound(i, j)` is a lower bound on the sum of costs of i and j in
/// any plan where they do not conflict. Adding constraints only raises the pair's optimum, so
/// in a constraint-tree node whose paths cost c_i, agents i and j together still need at least
/// delta_ij = bound(i, j) - c_i - c_j more, so the least total extra cost x_1 + ... + x_n with
/// x_i + x_j >= delta_ij on every pair (WDG's edge-weighted minimum vertex cover) is an
/// admissible heuristic for the node. It is computed exactly on small connected groups of
/// pairs (by a bounded depth-first search) and bounded from below by a matching (pairs sharing
/// no agent) on larger ones or when that search runs out of steps.
#include <cstddef>
#include <utility>
#include <vector>

namespace fleet_planner {

class PairwiseDelayBound {
 public:
  static constexpr int kExactCoverSize = 6;
  static constexpr long long kExactCoverCalls = 20000;  ///< beyond: the matching bound

  explicit PairwiseDelayBound(int agents) : n_(agents), bound_(static_cast<std::size_t>(agents) * agents, -1) {}

  /// A lower bound on the cost of agents i and j together (i != j).
  void set(int i, int j, long long bound);
  bool known(int i, int j) const { return bound_[index(i, j)] >= 0; }

  /// The heuristic for the per-agent path costs `costs`: the minimum vertex cover of the deltas
  /// on connected groups of up to kExactCoverSize agents (found within kExactCoverCalls steps),
  /// else a greedy matching (largest deltas first, ties by agent indices); 0 when no pair needs
  /// more than its paths cost. Deterministic.
  long long heuristic(const std::vector<int>& costs) const;

 private:
  std::size_t index(int i, int j) const {
    return i < j ? static_cast<std::size_t>(i) * n_ + j : static_cast<std::size_t>(j) * n_ + i;
  }
  int n_;
  std::vector<long long> bound_;
  std::vector<std::pair<int, int>> known_pairs_;  // in the order they were set
};

}  // namespace fleet_planner
