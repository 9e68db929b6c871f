// State-graph building on the shared benchmark maps: one StateGraph (one footprint), and a whole
// fleet's FleetGraphs (graphs shared between robots whose footprints cover the same cells).
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "bench_problems.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/obstacle_index.h"
#include "fleet_planner/model/state_graph.h"

namespace fleet_planner::bench {
namespace {

/// The obstacle index of a map (distance transform + row prefix counts).
void BM_ObstacleIndex(benchmark::State& state, const char* map) {
  std::string error;
  Problem* p = problem(map, 1, error);
  if (p == nullptr) return state.SkipWithError(error.c_str());
  for (auto _ : state) benchmark::DoNotOptimize(ObstacleIndex(p->map));
}
BENCHMARK_CAPTURE(BM_ObstacleIndex, Berlin_1_256, "Berlin_1_256")->Unit(benchmark::kMillisecond);

/// One robot's state graph (a 2.6 x 2.2 block) on a map, obstacle index prebuilt.
void BM_StateGraph(benchmark::State& state, const char* map) {
  std::string error;
  Problem* p = problem(map, 1, error);
  if (p == nullptr) return state.SkipWithError(error.c_str());
  const ObstacleIndex obstacles(p->map);
  auto cells = std::make_shared<const FootprintCells>(Footprint::block(-1.4, -1.1, 1.2, 1.1));
  for (auto _ : state) benchmark::DoNotOptimize(StateGraph(p->map, obstacles, cells));
  state.SetItemsProcessed(state.iterations() * p->map.numCells() * kHeadings);  // state ids
}
BENCHMARK_CAPTURE(BM_StateGraph, Berlin_1_256, "Berlin_1_256")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StateGraph, den520d, "den520d")->Unit(benchmark::kMillisecond);

/// Every graph of a fleet of K "mixed" robots, on one thread.
void BM_FleetGraphs(benchmark::State& state, const char* map) {
  std::string error;
  Problem* p = problem(map, static_cast<int>(state.range(0)), error);
  if (p == nullptr) return state.SkipWithError(error.c_str());
  std::vector<Footprint> footprints;
  for (const auto& r : p->instance.robots) footprints.push_back(r.footprint);
  int graphs = 0;
  for (auto _ : state) {
    FleetGraphs g(p->map, footprints, ActionModel{}, 1);
    graphs = g.numGraphs();
  }
  state.counters["graphs"] = graphs;
}
BENCHMARK_CAPTURE(BM_FleetGraphs, Berlin_1_256, "Berlin_1_256")->Arg(40)->Arg(140)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fleet_planner::bench
