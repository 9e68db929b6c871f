// Units of work on the thread pool, and merging their plans (Algorithm 5); see solving.h.
#include <algorithm>
#include <thread>

#include "fleet_planner/layered/plan_merge.h"
#include "solving.h"

namespace fleet_planner {

// Units of work: a subproblem (parallel backends) or the unsolved rest of a cluster's chain
// (serial backends), in order. A chain behind a failed level waits until a merge resolves it.
std::vector<std::vector<std::size_t>> Solving::pendingUnits() const {
  std::vector<std::vector<std::size_t>> units;
  std::vector<int> failed_clusters;
  for (std::size_t k = 0; k < order_.size(); ++k) {
    if (results_[k] && !results_[k]->success()) failed_clusters.push_back(order_[k].cluster);
    if (results_[k]) continue;
    if (serial_ && std::find(failed_clusters.begin(), failed_clusters.end(), order_[k].cluster) !=
                       failed_clusters.end()) {
      continue;
    }
    const bool chained = serial_ && !units.empty() && order_[units.back().back()].cluster == order_[k].cluster &&
                         units.back().back() + 1 == k;
    if (chained) {
      units.back().push_back(k);
    } else {
      units.push_back({k});
    }
  }
  return units;
}

void Solving::solvePending() {
  const auto units = pendingUnits();
  if (units.empty()) return;
  int pending = 0;
  for (const auto& u : units) {
    for (std::size_t k : u) pending += robotsOf(k);
  }
  pending_robots_ = pending;
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t u = next++; u < units.size(); u = next++) {
      for (std::size_t i = 0; i < units[u].size(); ++i) {
        const std::size_t k = units[u][i];
        solveOne(k);
        pending_robots_ -= robotsOf(k);
        if (results_[k]->success()) continue;
        // The rest of the chain plans around it: not in this round.
        for (std::size_t j = i + 1; j < units[u].size(); ++j)
          pending_robots_ -= robotsOf(units[u][j]);
        break;
      }
    }
  };
  const int threads = std::max(1, std::min<int>(options_.threads, static_cast<int>(units.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
}

// Algorithm 5: each unit's paths, delayed at the starts until they fit among the earlier ones.
std::vector<Path> Solving::mergePlans() {
  const int n = static_cast<int>(instance_.robots.size());
  std::vector<Path> paths(n);
  std::vector<char> done(n, 0);
  for (std::size_t k = 0; k < order_.size();) {
    std::size_t end = k + 1;
    if (serial_) {
      while (end < order_.size() && order_[end].cluster == order_[k].cluster) ++end;
    }
    std::vector<int> robots;
    std::vector<Path> fresh;
    for (std::size_t m = k; m < end; ++m) {
      robots.insert(robots.end(), order_[m].robots.begin(), order_[m].robots.end());
      robots.insert(robots.end(), order_[m].stepping_aside.begin(), order_[m].stepping_aside.end());
      fresh.insert(fresh.end(), results_[m]->paths.begin(), results_[m]->paths.end());
    }
    const int delay = delayToFit(graphs_, paths, done, robots, fresh);
    for (std::size_t a = 0; a < robots.size(); ++a) {
      appendDelayed(paths, robots[a], std::move(fresh[a]));
      done[robots[a]] = 1;
    }
    for (std::size_t m = k; m < end; ++m) order_[m].delay = delay;
    k = end;
  }
  return paths;
}

}  // namespace fleet_planner
