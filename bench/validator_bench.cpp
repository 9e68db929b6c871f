// The independent plan validator on real plans: layered LA-LaCAM plans for "K mixed" robots,
// planned once (seed 0) before timing.
#include <benchmark/benchmark.h>

#include <string>

#include "bench_problems.h"
#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/layered/layered_planner.h"

namespace fleet_planner::bench {
namespace {

void BM_ValidatePlan(benchmark::State& state, const char* map) {
  std::string error;
  Problem* p = problem(map, static_cast<int>(state.range(0)), error);
  if (p == nullptr) return state.SkipWithError(error.c_str());
  LayeredOptions options;
  options.backend = "la_lacam";
  const LayeredResult result = planLayered(p->map, p->instance, p->fleetGraphs(), options, Deadline::in(60));
  if (!result.success()) return state.SkipWithError(("no plan to validate: " + result.reason).c_str());
  bool valid = false;
  for (auto _ : state) valid = validatePlan(p->map, p->instance, result.plan).valid();
  if (!valid) state.SkipWithError("the plan failed validation");
  state.counters["makespan"] = result.metrics.makespan;
  state.SetItemsProcessed(state.iterations() * result.metrics.makespan);  // time steps checked
}
BENCHMARK_CAPTURE(BM_ValidatePlan, AR0044SR, "AR0044SR")->Arg(40)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ValidatePlan, Berlin_1_256, "Berlin_1_256")->Arg(40)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fleet_planner::bench
