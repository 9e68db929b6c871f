// The decomposition pipeline: relation graphs, then steps 1-4 (paper, Methodology; the
// solving part of Algorithm 6 lives in the layered planner).
#include <algorithm>
#include <chrono>

#include "dependency_oracle.h"
#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/decomposition/decomposition.h"
#include "fleet_planner/decomposition/relation_graph.h"

namespace fleet_planner {

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

DecompositionStep stats(int step, const std::vector<std::vector<int>>& parts, double time_s) {
  DecompositionStep s;
  s.step = step;
  s.subproblems = static_cast<int>(parts.size());
  for (const auto& p : parts) s.largest = std::max(s.largest, static_cast<int>(p.size()));
  s.time_s = time_s;
  return s;
}

}  // namespace

int Decomposition::largest() const {
  int m = 0;
  for (const auto& s : subproblems) m = std::max(m, static_cast<int>(s.robots.size()));
  return m;
}

double Decomposition::rate(int robots) const { return robots > 0 ? static_cast<double>(largest()) / robots : 0.0; }

Decomposition decompose(const Instance& instance, const FleetGraphs& graphs, const DecompositionOptions& options,
                        const Deadline& deadline) {
  if (options.last_step < 1 || options.last_step > 4) {
    throw InvalidInput("decomposition steps must be 1 to 4, got " + std::to_string(options.last_step));
  }
  Decomposition d;
  const int n = static_cast<int>(instance.robots.size());
  if (n == 0) return d;
  auto t = std::chrono::steady_clock::now();
  const std::vector<RelationGraph> relations = buildRelationGraphs(instance, graphs, options.threads, deadline);
  d.relations_s = since(t);
  const bool all_built = std::all_of(relations.begin(), relations.end(), [](const RelationGraph& r) { return r.graph; });
  if (!all_built) {
    // Out of time before step 1: the whole fleet as one subproblem, legal by definition.
    d.complete = false;
    d.pairs_complete = false;
    DecompositionSubproblem all;
    for (int i = 0; i < n; ++i) all.robots.push_back(i);
    d.subproblems.push_back(std::move(all));
    return d;
  }
  detail::DependencyOracle oracle(relations);
  for (int i = 0; i < n; ++i) {
    if (!oracle.agents(i, {}, {})) {
      throw InvalidInput(robotLabel(instance.robots[i]) + ": target is not reachable from start for its footprint");
    }
  }

  // Steps 1 and 2: clusters.
  t = std::chrono::steady_clock::now();
  std::vector<std::vector<int>> clusters = detail::initialClusters(oracle, deadline);
  d.steps.push_back(stats(1, clusters, since(t)));
  if (options.last_step >= 2 && !deadline.expired()) {
    t = std::chrono::steady_clock::now();
    clusters = detail::bipartitionClusters(oracle, clusters, deadline);
    d.steps.push_back(stats(2, clusters, since(t)));
  }
  std::sort(clusters.begin(), clusters.end());  // by smallest robot: deterministic
  std::vector<std::vector<std::vector<int>>> levels(clusters.size());
  for (std::size_t c = 0; c < clusters.size(); ++c) levels[c] = {clusters[c]};

  // Steps 3 and 4: levels inside each cluster.
  auto flat = [&] {
    std::vector<std::vector<int>> all;
    for (const auto& ls : levels) all.insert(all.end(), ls.begin(), ls.end());
    return all;
  };
  if (options.last_step >= 3 && !deadline.expired()) {
    t = std::chrono::steady_clock::now();
    for (std::size_t c = 0; c < clusters.size(); ++c) levels[c] = detail::initialLevels(oracle, clusters[c]);
    d.steps.push_back(stats(3, flat(), since(t)));
  }
  if (options.last_step >= 4 && !deadline.expired()) {
    t = std::chrono::steady_clock::now();
    for (std::size_t c = 0; c < clusters.size(); ++c) {
      levels[c] = detail::bipartitionLevels(oracle, clusters[c], levels[c], deadline, options.peel_levels);
    }
    d.steps.push_back(stats(4, flat(), since(t)));
  }
  d.complete = static_cast<int>(d.steps.size()) == options.last_step && !deadline.expired();
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    for (std::size_t l = 0; l < levels[c].size(); ++l) {
      d.subproblems.push_back({levels[c][l], static_cast<int>(c), static_cast<int>(l)});
    }
  }
  t = std::chrono::steady_clock::now();
  for (const auto& s : d.subproblems) {
    const auto pairs = detail::entangledPairs(oracle, s.robots, deadline);
    d.entangled_pairs.insert(d.entangled_pairs.end(), pairs.begin(), pairs.end());
  }
  d.pairs_complete = !deadline.expired();
  d.entangled_s = since(t);
  return d;
}

}  // namespace fleet_planner
