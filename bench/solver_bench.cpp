// Backend kernels: LA-LaCAM's configuration rate on packed fleets, LA-LNS's first plan, and the
// joint search of a knot.
// Each run plans the pool's "K mixed" robots as one subproblem (raw), on one thread, for a fixed
// budget of low-level expansions, so that every machine does the same work. The time reported
// is the search's: the same solve with a budget of one step (distance tables and the first
// configuration) is timed too and taken off.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <string>

#include "bench_problems.h"
#include "fleet_planner/solvers/lns/parking_plan.h"
#include "fleet_planner/solvers/registry.h"
#include "fleet_planner/solvers/search/joint_path_search.h"
#include "fleet_planner/solvers/search/soft_path_table.h"
#include "fleet_planner/solvers/search/search_space.h"
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner::bench {
namespace {

/// LA-LaCAM for 20,000 configuration steps (one PIBT step each): `configs/s` counts the new
/// configurations, `steps/s` every step (revisits included).
void lacamConfigurations(benchmark::State& state, Problem* p, const std::string& error) {
  if (p == nullptr) return state.SkipWithError(error.c_str());
  const Subproblem sub = wholeFleet(*p, 20000), setup = wholeFleet(*p, 0);
  long long configs = 0, steps = 0;
  std::string outcome;
  using Clock = std::chrono::steady_clock;
  for (auto _ : state) {
    const Clock::time_point t0 = Clock::now();
    const SolveResult first = makeSolver("la_lacam")->solve(setup);
    const Clock::time_point t1 = Clock::now();
    const SolveResult r = makeSolver("la_lacam")->solve(sub);
    const Clock::time_point t2 = Clock::now();
    state.SetIterationTime(std::chrono::duration<double>((t2 - t1) - (t1 - t0)).count());
    configs += r.stats.high_level_nodes - first.stats.high_level_nodes;
    steps += r.stats.low_level_expansions - first.stats.low_level_expansions;
    outcome = statusName(r.status);
  }
  state.counters["configs/s"] = benchmark::Counter(static_cast<double>(configs), benchmark::Counter::kIsRate);
  state.counters["steps/s"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
  state.SetLabel(outcome);
}

void BM_LaLacamConfigurations(benchmark::State& state, const char* map) {
  std::string error;
  Problem* p = problem(map, static_cast<int>(state.range(0)), error);
  lacamConfigurations(state, p, error);
}

/// The same on a generated fleet (`fleet_planner_cli generate --seed 1`): the size of the city
/// fleets that the pools do not reach.
void BM_LaLacamConfigurationsGenerated(benchmark::State& state, const char* map) {
  std::string error;
  Problem* p = generatedProblem(map, static_cast<int>(state.range(0)), 1, error);
  lacamConfigurations(state, p, error);
}
/// LA-LNS's parking plan (parking_plan.h) of a generated city fleet, longest way first, for a
/// fixed budget of 3 million expansions of its searches (most of them safe interval searches of
/// legs home among hundreds of paths): `expansions/s`. The set-up (distance tables) is not
/// timed.
void BM_ParkingPlan(benchmark::State& state, const char* map) {
  std::string error;
  Problem* p = generatedProblem(map, static_cast<int>(state.range(0)), 1, error);
  if (p == nullptr) return state.SkipWithError(error.c_str());
  const Subproblem sub = wholeFleet(*p, -1);
  const SearchSpace space(sub);
  std::vector<int> order(space.numAgents());
  for (int a = 0; a < space.numAgents(); ++a) order[a] = a;
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) {
    return space.distance(x, space.start(x)) > space.distance(y, space.start(y));
  });
  ParkingPlanOptions o;
  o.max_expansions = 3'000'000;
  long long expansions = 0;
  int home = 0;
  for (auto _ : state) {
    const std::optional<ParkingPlan> plan = parkingPlan(space, order, sub.deadline, o, expansions);
    home = plan ? plan->robots_home : -1;
  }
  state.counters["expansions/s"] =
      benchmark::Counter(static_cast<double>(expansions), benchmark::Counter::kIsRate);
  state.counters["home"] = home;
}

/// The joint search (joint_path_search.h) of robots 6 and 9 of AR0203SR's pool of 10, the pair
/// that must wait for each other in a diagonal corridor, alone, for 200,000 joint states (it
/// needs more): `expansions/s`. The set-up (distance tables) is not timed.
void BM_JointSearch(benchmark::State& state) {
  std::string error;
  Problem* p = problem("AR0203SR", 10, error);
  if (p == nullptr) return state.SkipWithError(error.c_str());
  const Subproblem sub = wholeFleet(*p, -1);
  const SearchSpace space(sub);
  const SoftPathTable nobody(space);
  JointSearchOptions o;
  o.max_nodes = 200'000;
  long long expansions = 0;
  for (auto _ : state) expansions += jointPathSearch(space, {6, 9}, nobody, sub.deadline, o).expansions;
  state.counters["expansions/s"] =
      benchmark::Counter(static_cast<double>(expansions), benchmark::Counter::kIsRate);
}

BENCHMARK_CAPTURE(BM_ParkingPlan, Paris_1_256, "Paris_1_256")->Arg(300)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LaLacamConfigurations, maze-128-128-10, "maze-128-128-10")->Arg(50)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LaLacamConfigurations, Paris_1_256, "Paris_1_256")->Arg(140)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LaLacamConfigurations, AR0044SR, "AR0044SR")->Arg(100)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LaLacamConfigurationsGenerated, Paris_1_256, "Paris_1_256")->Arg(300)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_JointSearch)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fleet_planner::bench
