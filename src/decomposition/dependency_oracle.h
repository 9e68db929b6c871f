#pragma once
// The dependency queries the decomposition algorithms ask, in terms of robots and SAT sets
// (masks over robots, or over SATs: 2j = start of robot j, 2j + 1 = its target).
#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/decomposition/dependency_search.h"

namespace fleet_planner::detail {

using Mask = std::vector<char>;

class DependencyOracle {
 public:
  DependencyOracle(const std::vector<RelationGraph>& graphs)
      : graphs_(graphs), n_(static_cast<int>(graphs.size())), witness_(graphs.size()) {}

  int robots() const { return n_; }

  /// search_path_agent: the robots robot i's path is related to, through components related only
  /// to robots in `avail` (empty mask: any) and to none in `avoid` (empty: none).
  std::optional<std::vector<int>> agents(int i, const Mask& avail, const Mask& avoid) {
    auto sats = query(i, robotFilter(avail, avoid));
    if (!sats) return std::nullopt;
    std::vector<int> out;
    for (int s : *sats) {
      if (out.empty() || out.back() != s / 2) out.push_back(s / 2);
    }
    return out;
  }

  /// search_path_SAT: the SATs robot i's path is related to, through components whose SATs are
  /// all in `avail` (empty: any) and none in `avoid` (empty: none).
  std::optional<std::vector<int>> sats(int i, const Mask& avail, const Mask& avoid) {
    return query(i, SatFilter{avail, avoid});
  }

  /// Whether agents(i, avail, avoid) would find a path (a cheaper search that ranks no paths).
  bool agentPathExists(int i, const Mask& avail, const Mask& avoid) { return exists(i, robotFilter(avail, avoid)); }

  /// Whether sats(i, avail, avoid) would find a path.
  bool satPathExists(int i, const Mask& avail, const Mask& avoid) { return exists(i, SatFilter{avail, avoid}); }

  long long queries() const { return queries_; }

 private:
  std::optional<std::vector<int>> query(int i, const SatFilter& f) {
    ++queries_;
    auto sats = searchPathSats(graphs_[i], f);
    if (sats) witness_[i] = *sats;
    return sats;
  }
  // The decomposition asks the same robot many times with slightly different filters: the last
  // path found for it answers "yes" without a search whenever the filter passes all its SATs.
  bool exists(int i, const SatFilter& f) {
    ++queries_;
    if (const auto& w = witness_[i]; w && std::all_of(w->begin(), w->end(), [&](int s) { return f.passes(s); })) {
      return true;
    }
    std::vector<int> found;
    if (!pathExists(graphs_[i], f, &found)) return false;
    witness_[i] = std::move(found);
    return true;
  }
  // Masks over robots as a filter over their SATs (empty masks stay empty: no restriction).
  SatFilter robotFilter(const Mask& avail, const Mask& avoid) const {
    SatFilter f;
    if (!avail.empty()) f.allowed = satsOf(avail);
    if (!avoid.empty()) f.avoided = satsOf(avoid);
    return f;
  }
  Mask satsOf(const Mask& robots) const {
    Mask m(2 * n_, 0);
    for (int j = 0; j < n_; ++j) m[2 * j] = m[2 * j + 1] = robots[j];
    return m;
  }

  const std::vector<RelationGraph>& graphs_;
  int n_;
  std::vector<std::optional<std::vector<int>>> witness_;  // SATs of the last path found per robot
  long long queries_ = 0;
};

inline Mask maskOf(const std::vector<int>& robots, int n) {
  Mask m(n, 0);
  for (int r : robots) m[r] = 1;
  return m;
}

/// Algorithm 1, first half: connected components of the relevance graph (ascending robots).
std::vector<std::vector<int>> initialClusters(DependencyOracle& oracle, const Deadline& deadline);
/// Algorithm 1, second half, with Algorithm 2: bipartition each cluster until none splits.
std::vector<std::vector<int>> bipartitionClusters(DependencyOracle& oracle, const std::vector<std::vector<int>>& clusters,
                                                  const Deadline& deadline);
/// Algorithm 3, first half: strongly connected components of the solving-order graph of one
/// cluster, in solving order.
std::vector<std::vector<int>> initialLevels(DependencyOracle& oracle, const std::vector<int>& cluster);
/// Algorithm 3, second half, with Algorithm 4: bipartition each level until none splits; with
/// `peel`, first peel off robots that can go before or after all others of their level.
std::vector<std::vector<int>> bipartitionLevels(DependencyOracle& oracle, const std::vector<int>& cluster,
                                                const std::vector<std::vector<int>>& levels, const Deadline& deadline,
                                                bool peel);
/// The pairs (a < b) of `robots` that can go one after the other in neither order, each alone on
/// the map (Decomposition::entangled_pairs); those found so far once the deadline passes.
std::vector<std::pair<int, int>> entangledPairs(DependencyOracle& oracle,
                                                const std::vector<int>& robots,
                                                const Deadline& deadline);

}  // namespace fleet_planner::detail
