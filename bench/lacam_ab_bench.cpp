// LA-LaCAM's configuration rate, two versions in one process (scripts/lacam_ab compiles them in
// as the solvers "la_lacam_ab_base" and "la_lacam_ab_new"; without them this benchmark skips).
// Each iteration runs both searches of 20,000 configuration steps, in alternating order, and
// adds up the time of their searches alone (distance tables excluded), so that the machine's
// changes of speed fall on both alike.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <vector>

#include "bench_problems.h"
#include "fleet_planner/solvers/registry.h"
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {
// Defined by the copies that scripts/lacam_ab makes; absent (null) otherwise.
extern double g_lacam_ab_base_s __attribute__((weak));
extern double g_lacam_ab_new_s __attribute__((weak));
}  // namespace fleet_planner

namespace fleet_planner::bench {
namespace {

void compare(benchmark::State& state, Problem* p, const std::string& error) {
  if (p == nullptr) return state.SkipWithError(error.c_str());
  const std::vector<std::string> names = solverNames();
  auto registered = [&](const char* name) { return std::find(names.begin(), names.end(), name) != names.end(); };
  if (&g_lacam_ab_base_s == nullptr || &g_lacam_ab_new_s == nullptr || !registered("la_lacam_ab_base") ||
      !registered("la_lacam_ab_new")) {
    return state.SkipWithError("no versions to compare: run scripts/lacam_ab");
  }
  const Subproblem sub = wholeFleet(*p, 20000);
  double base_s = 0, new_s = 0;
  long long base_nodes = 0, new_nodes = 0, rounds = 0;
  for (auto _ : state) {
    const double base_before = g_lacam_ab_base_s, new_before = g_lacam_ab_new_s;
    for (int k = 0; k < 2; ++k) {
      if ((k + rounds) % 2 == 0) {
        base_nodes += makeSolver("la_lacam_ab_base")->solve(sub).stats.high_level_nodes;
      } else {
        new_nodes += makeSolver("la_lacam_ab_new")->solve(sub).stats.high_level_nodes;
      }
    }
    base_s += g_lacam_ab_base_s - base_before;
    new_s += g_lacam_ab_new_s - new_before;
    ++rounds;
  }
  state.counters["base_ms"] = 1000.0 * base_s / static_cast<double>(rounds);
  state.counters["new_ms"] = 1000.0 * new_s / static_cast<double>(rounds);
  state.counters["base/new"] = new_s > 0 ? base_s / new_s : 0.0;
  state.counters["same_configs"] = base_nodes == new_nodes;
}

void BM_LaLacamAB(benchmark::State& state, const char* map) {
  std::string error;
  compare(state, problem(map, static_cast<int>(state.range(0)), error), error);
}

void BM_LaLacamABGenerated(benchmark::State& state, const char* map) {
  std::string error;
  compare(state, generatedProblem(map, static_cast<int>(state.range(0)), 1, error), error);
}

BENCHMARK_CAPTURE(BM_LaLacamAB, maze-128-128-10, "maze-128-128-10")->Arg(50)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LaLacamAB, Paris_1_256, "Paris_1_256")->Arg(140)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LaLacamAB, AR0044SR, "AR0044SR")->Arg(100)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LaLacamABGenerated, Paris_1_256, "Paris_1_256")->Arg(300)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fleet_planner::bench
