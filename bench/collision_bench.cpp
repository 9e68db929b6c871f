// Footprint and sweep kernels: discretising a footprint (FootprintCells) and the CellSet overlap
// test behind every vertex and transfer conflict check.
#include <benchmark/benchmark.h>

#include <vector>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/model/footprint_cells.h"

namespace fleet_planner::bench {
namespace {

Footprint circle() { return Footprint::circle(1.5); }
Footprint block() { return Footprint::block(-1.4, -1.1, 1.2, 1.1); }
Footprint polygon() { return Footprint::polygon({{1.8, 0.0}, {-1.0, 1.2}, {-0.4, 0.0}, {-1.0, -1.2}}); }

/// Discretising one footprint: its body at 4 headings and its sweeps for every action.
void BM_FootprintCells(benchmark::State& state, Footprint (*make)()) {
  const Footprint f = make();
  for (auto _ : state) benchmark::DoNotOptimize(FootprintCells(f));
}
BENCHMARK_CAPTURE(BM_FootprintCells, circle_r1.5, circle)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_FootprintCells, block_2.6x2.2, block)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_FootprintCells, polygon_4, polygon)->Unit(benchmark::kMicrosecond);

/// Placements of robot B around robot A within `reach` cells in x and y.
std::vector<Cell> offsets(int reach) {
  std::vector<Cell> out;
  for (int dy = -reach; dy <= reach; ++dy)
    for (int dx = -reach; dx <= reach; ++dx) out.push_back({dx, dy});
  return out;
}

/// Vertex checks (footprintsOverlap) of a block against a circle at every offset up to `reach`
/// cells and every heading pair: near offsets overlap, far ones fail the bounding-box test.
void BM_FootprintOverlap(benchmark::State& state) {
  const FootprintCells a(block()), b(circle());
  const std::vector<Cell> places = offsets(static_cast<int>(state.range(0)));
  long long hits = 0;
  for (auto _ : state) {
    for (const Cell& c : places)
      for (int ha = 0; ha < kHeadings; ++ha)
        for (int hb = 0; hb < kHeadings; ++hb) hits += footprintsOverlap(a, {10, 10, ha}, b, {10 + c.x, 10 + c.y, hb});
  }
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(state.iterations() * static_cast<long long>(places.size()) * kHeadings * kHeadings);
}
BENCHMARK(BM_FootprintOverlap)->Arg(3)->Arg(6)->Unit(benchmark::kMicrosecond);

/// Transfer checks (sweepsOverlap): both robots rotate or move, at every offset up to 6 cells.
void BM_SweepOverlap(benchmark::State& state) {
  const FootprintCells a(block()), b(polygon());
  const std::vector<Cell> places = offsets(6);
  const Action actions[] = {Action::Forward, Action::RotateCcw, Action::RotateCw};
  long long hits = 0;
  for (auto _ : state) {
    for (const Cell& c : places)
      for (Action aa : actions)
        for (Action ab : actions) hits += sweepsOverlap(a, {10, 10, 0}, aa, b, {10 + c.x, 10 + c.y, 2}, ab);
  }
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(state.iterations() * static_cast<long long>(places.size()) * 9);
}
BENCHMARK(BM_SweepOverlap)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace fleet_planner::bench
