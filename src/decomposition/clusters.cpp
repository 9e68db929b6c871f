// Decomposition into clusters: paper, Methodology, Algorithms 1 and 2.
#include <algorithm>
#include <numeric>

#include "dependency_oracle.h"
#include "fleet_planner/runtime/errors.h"

namespace fleet_planner::detail {

namespace {

// Connected components of an undirected graph given as adjacency masks; ascending members,
// ordered by their smallest member.
std::vector<std::vector<int>> components(const std::vector<int>& nodes, const std::vector<std::vector<int>>& adjacent) {
  std::vector<std::vector<int>> out;
  std::vector<char> seen(adjacent.size(), 0);
  for (int start : nodes) {
    if (seen[start]) continue;
    std::vector<int> comp{start}, queue{start};
    seen[start] = 1;
    for (std::size_t h = 0; h < queue.size(); ++h) {
      for (int next : adjacent[queue[h]]) {
        if (!seen[next]) {
          seen[next] = 1;
          queue.push_back(next);
          comp.push_back(next);
        }
      }
    }
    std::sort(comp.begin(), comp.end());
    out.push_back(std::move(comp));
  }
  return out;
}

std::vector<int> members(const Mask& m) {
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(m.size()); ++i) {
    if (m[i]) out.push_back(i);
  }
  return out;
}

// Algorithm 2: splits c into a major set and a remainder that are both clusters (the remainder
// may be empty). Past the deadline, c stays whole (still legal).
std::pair<std::vector<int>, std::vector<int>> bipartition(DependencyOracle& oracle, const std::vector<int>& c,
                                                          const Deadline& deadline) {
  const int n = oracle.robots();
  if (c.size() <= 1) return {c, {}};
  const Mask in_c = maskOf(c, n);
  // Step 1: unavoidance graph; the major set is its largest connected component. Only robots
  // on i's best path inside c can be unavoidable: i's path already avoids every other one.
  std::vector<std::vector<int>> adjacent(n);
  for (int i : c) {
    if (deadline.expired()) return {c, {}};
    const auto on_path = oracle.agents(i, in_c, {});
    if (!on_path) throw InvalidInput("decomposition: a robot lost its path inside its own cluster");
    for (int j : *on_path) {
      Mask avoid(n, 0);
      avoid[j] = 1;
      if (!oracle.agentPathExists(i, in_c, avoid)) {
        adjacent[i].push_back(j);
        adjacent[j].push_back(i);
      }
    }
  }
  std::vector<std::vector<int>> parts = components(c, adjacent);
  const auto largest = std::max_element(parts.begin(), parts.end(),
                                        [](const auto& a, const auto& b) { return a.size() < b.size(); });
  Mask major = maskOf(*largest, n), remain = in_c;
  for (int i : *largest) remain[i] = 0;

  auto move = [&](int i) {
    remain[i] = 0;
    major[i] = 1;
  };
  for (;;) {
    if (deadline.expired()) return {c, {}};
    // Step 2: remainder robots that cannot keep clear of the major set join it.
    for (bool moved = true; moved;) {
      moved = false;
      for (int i : members(remain)) {
        if (!oracle.agentPathExists(i, remain, major)) {
          move(i);
          moved = true;
        }
      }
    }
    // Step 3: major robots that cannot keep clear of the remainder pull in what they need.
    for (bool moved = true; moved;) {
      moved = false;
      for (int i : members(major)) {
        if (oracle.agentPathExists(i, major, remain)) continue;
        const auto needed = oracle.agents(i, in_c, {});
        if (!needed) throw InvalidInput("decomposition: a robot lost its path inside its own cluster");
        for (int j : *needed) {
          if (remain[j]) {
            move(j);
            moved = true;
          }
        }
      }
    }
    // Step 4: done when both sets are independent clusters.
    const std::vector<int> rest = members(remain);
    if (rest.empty()) break;
    bool independent = true;
    for (int i : rest) independent = independent && oracle.agentPathExists(i, remain, major);
    for (int i : members(major)) independent = independent && oracle.agentPathExists(i, major, remain);
    if (independent) break;
  }
  return {members(major), members(remain)};
}

}  // namespace

std::vector<std::vector<int>> initialClusters(DependencyOracle& oracle, const Deadline& deadline) {
  (void)deadline;
  const int n = oracle.robots();
  std::vector<std::vector<int>> adjacent(n);
  for (int i = 0; i < n; ++i) {
    const auto related = oracle.agents(i, {}, {});
    if (!related) throw InvalidInput("decomposition: robot index " + std::to_string(i) + " has no path to its target");
    for (int j : *related) {
      adjacent[i].push_back(j);
      adjacent[j].push_back(i);
    }
  }
  std::vector<int> all(n);
  std::iota(all.begin(), all.end(), 0);
  return components(all, adjacent);
}

std::vector<std::vector<int>> bipartitionClusters(DependencyOracle& oracle, const std::vector<std::vector<int>>& clusters,
                                                  const Deadline& deadline) {
  std::vector<std::vector<int>> out;
  for (const auto& c : clusters) {
    std::vector<int> rest = c;
    while (!rest.empty()) {
      if (deadline.expired()) {
        out.push_back(rest);  // what is left stays one cluster: still legal
        break;
      }
      auto [major, remain] = bipartition(oracle, rest, deadline);
      out.push_back(std::move(major));
      rest = std::move(remain);
    }
  }
  return out;
}

}  // namespace fleet_planner::detail
