// Decomposition kernels: the relation (component connectivity) graphs, the dependency search
// over them (search_path_SAT), and the whole decomposition, steps 1-4, on one thread.
#include <benchmark/benchmark.h>

#include <string>

#include "bench_problems.h"
#include "fleet_planner/decomposition/decomposition.h"
#include "fleet_planner/decomposition/dependency_search.h"
#include "fleet_planner/decomposition/relation_graph.h"

namespace fleet_planner::bench {
namespace {

/// Every robot's relation graph (one component graph per distinct state graph).
void BM_RelationGraphs(benchmark::State& state, const char* map) {
  std::string error;
  Problem* p = problem(map, static_cast<int>(state.range(0)), error);
  if (p == nullptr) return state.SkipWithError(error.c_str());
  const FleetGraphs& graphs = p->fleetGraphs();
  for (auto _ : state) benchmark::DoNotOptimize(buildRelationGraphs(p->instance, graphs, 1));
}
BENCHMARK_CAPTURE(BM_RelationGraphs, empty-48-48, "empty-48-48")->Arg(40)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RelationGraphs, AR0044SR, "AR0044SR")->Arg(60)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RelationGraphs, Berlin_1_256, "Berlin_1_256")->Arg(40)->Unit(benchmark::kMillisecond);

/// The dependency search of every robot of the fleet: once with every SAT allowed, once
/// avoiding the SATs of the robots before it (the kind of query steps 2 and 4 make).
void BM_DependencySearch(benchmark::State& state, const char* map) {
  std::string error;
  Problem* p = problem(map, static_cast<int>(state.range(0)), error);
  if (p == nullptr) return state.SkipWithError(error.c_str());
  const auto relations = buildRelationGraphs(p->instance, p->fleetGraphs(), 1);
  const int n = static_cast<int>(relations.size());
  std::vector<SatFilter> filters(n);
  for (int i = 0; i < n; ++i) {
    filters[i].avoided.assign(2 * n, 0);
    for (int j = 0; j < i; ++j) filters[i].avoided[2 * j] = filters[i].avoided[2 * j + 1] = 1;
  }
  const SatFilter all;
  long long found = 0;
  for (auto _ : state) {
    for (int i = 0; i < n; ++i) {
      found += searchPathSats(relations[i], all).has_value();
      found += searchPathSats(relations[i], filters[i]).has_value();
    }
  }
  benchmark::DoNotOptimize(found);
  state.SetItemsProcessed(state.iterations() * 2 * n);  // searches
}
BENCHMARK_CAPTURE(BM_DependencySearch, empty-48-48, "empty-48-48")->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_DependencySearch, AR0044SR, "AR0044SR")->Arg(60)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_DependencySearch, Berlin_1_256, "Berlin_1_256")->Arg(40)->Unit(benchmark::kMicrosecond);

/// The whole decomposition, steps 1-4 (relation graphs included, state graphs prebuilt).
void BM_Decompose(benchmark::State& state, const char* map) {
  std::string error;
  Problem* p = problem(map, static_cast<int>(state.range(0)), error);
  if (p == nullptr) return state.SkipWithError(error.c_str());
  const FleetGraphs& graphs = p->fleetGraphs();
  DecompositionOptions options;
  int largest = 0;
  for (auto _ : state) largest = decompose(p->instance, graphs, options).largest();
  state.counters["largest"] = largest;
}
BENCHMARK_CAPTURE(BM_Decompose, empty-48-48, "empty-48-48")->Arg(40)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Decompose, AR0044SR, "AR0044SR")->Arg(60)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Decompose, Berlin_1_256, "Berlin_1_256")->Arg(40)->Arg(140)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fleet_planner::bench
