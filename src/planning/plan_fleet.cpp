// The planning facade; see plan_fleet.h.
#include "fleet_planner/planning/plan_fleet.h"

#include <memory>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/runtime/memory_guard.h"

namespace fleet_planner {

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

LayeredOptions layeredOptions(const PlanningOptions& o, int threads) {
  LayeredOptions l;
  l.backend = o.backend;
  l.fallback = o.fallback;
  l.backend_parameters = o.backend_parameters;
  l.budget = o.budget;
  l.decompose = o.decompose;
  l.last_step = o.last_step;
  l.threads = threads;
  l.independent_clusters = o.independent_clusters;
  l.refine = o.refine;
  l.compress = o.compress;
  l.seed = o.seed;
  l.precheck = false;  // done here, for both modes
  return l;
}

/// The status of a call whose deadline passed while the graphs were built.
void graphsNotBuilt(PlanningResult& result, const Deadline& deadline, const MemoryGuard& memory,
                    const DeadlineExpired& e) {
  result.status = deadline.outOfMemory() ? SolveStatus::ResourceLimit
                  : deadline.cancelled() ? SolveStatus::Cancelled
                                         : SolveStatus::Timeout;
  result.reason = deadline.outOfMemory() ? memory.reason() : e.what();
}

}  // namespace

PlanningResult planFleet(const GridMap& map, const Instance& instance, const PlanningOptions& options,
                         const PlanningCall& call) {
  const std::vector<std::string> problems = checkPlanningOptions(options);
  if (!problems.empty()) {
    std::string all;
    for (const std::string& p : problems) all += (all.empty() ? "" : "; ") + p;
    throw InvalidInput(all);
  }
  PlanningResult result;
  result.backend = options.backend;
  result.fallback = options.fallback;
  result.threads = effectiveThreads(options);
  result.layered = options.decompose;
  const MemoryGuard memory(options.limits.max_memory_mb);
  const Deadline deadline =
      Deadline::in(options.time_limit - since(call.started), call.cancel).withMemoryGuard(&memory);

  // State graphs: they count against the time limit like everything else.
  std::vector<Footprint> footprints;
  for (const Robot& r : instance.robots) footprints.push_back(r.footprint);
  const auto t_graphs = std::chrono::steady_clock::now();
  std::shared_ptr<const FleetGraphs> graphs;
  try {
    if (call.cache != nullptr) {
      graphs = call.cache->get(map, call.map_version, footprints, options.model, result.threads, options.limits,
                               deadline, result.graphs_cached);
    } else {
      graphs = std::make_shared<const FleetGraphs>(map, footprints, options.model, result.threads, options.limits,
                                                   deadline);
    }
  } catch (const DeadlineExpired& e) {
    graphsNotBuilt(result, deadline, memory, e);
  }
  result.precompute_s = result.graphs_cached ? 0.0 : since(t_graphs);

  if (graphs) {
    // The pre-check names every robot that cannot reach its target and every overlap.
    const auto t_check = std::chrono::steady_clock::now();
    result.precheck = checkSolvability(instance, *graphs, deadline);
    if (!result.precheck.solvable()) {
      const auto& found = result.precheck.problems;
      result.status = SolveStatus::Infeasible;
      result.reason = found.front().reason;
      if (found.size() > 1) result.reason += " (and " + std::to_string(found.size() - 1) + " more)";
      result.decompose_s = since(t_check);
    } else {
      const SolvabilityReport precheck = std::move(result.precheck);
      static_cast<LayeredResult&>(result) =
          planLayered(map, instance, *graphs, layeredOptions(options, result.threads), deadline);
      result.precheck = precheck;
    }
  }
  result.time_s = since(call.started);
  return result;
}

}  // namespace fleet_planner
