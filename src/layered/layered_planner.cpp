// Layered LA-MAPF: paper, Algorithms 5 and 6; see layered_planner.h.
#include "fleet_planner/layered/layered_planner.h"

#include <algorithm>
#include <chrono>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/model/instance_check.h"
#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/solvers/registry.h"

namespace fleet_planner {

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The subproblems to solve, in order: the decomposition's (at most its share of the time: one cut
// short is still legal, only coarser), or the whole fleet as one: raw, or a decomposition with a
// dominant subproblem (TimeBudget::whole_fleet_share; `as_one` says why, and the decomposition
// stays as computed).
std::vector<SolvedSubproblem> decomposeInto(const Instance& instance, const FleetGraphs& graphs,
                                            const LayeredOptions& options, const Deadline& deadline,
                                            Decomposition& decomposition, std::string& as_one) {
  const int n = static_cast<int>(instance.robots.size());
  std::vector<SolvedSubproblem> order;
  if (options.decompose && n > 0) {
    DecompositionOptions d;
    d.last_step = options.last_step;
    d.threads = options.threads;
    decomposition =
        decompose(instance, graphs, d, deadline.within(deadline.remaining() * options.budget.decomposition_share));
    const std::size_t largest = static_cast<std::size_t>(decomposition.largest());
    if (decomposition.subproblems.size() > 1 && largest >= options.budget.whole_fleet_min_robots &&
        largest >= options.budget.whole_fleet_share * n) {
      as_one = "the decomposition's largest subproblem holds " + std::to_string(largest) + " of " +
               std::to_string(n) + " robots: the fleet is solved as one subproblem";
    } else {
      for (const auto& s : decomposition.subproblems) {
        SolvedSubproblem solved;
        solved.robots = s.robots;
        solved.cluster = s.cluster;
        solved.level = s.level;
        order.push_back(solved);
      }
      return order;
    }
  }
  SolvedSubproblem all;
  for (int i = 0; i < n; ++i) all.robots.push_back(i);
  order.push_back(all);
  if (!as_one.empty()) return order;  // the decomposition stays reported as computed
  DecompositionSubproblem whole;
  whole.robots = all.robots;
  decomposition.subproblems.push_back(whole);
  return order;
}

SubproblemSolvingOptions solvingOptions(const LayeredOptions& options, const Decomposition& decomposition) {
  SubproblemSolvingOptions s;
  s.backend = options.backend;
  s.fallback = options.fallback;
  s.threads = options.threads;
  s.seed = options.seed;
  s.backend_parameters = options.backend_parameters;
  s.budget = options.budget;
  s.entangled_pairs = decomposition.entangled_pairs;
  s.entangled_known = options.decompose && decomposition.pairs_complete;
  s.whole_fleet_ends_when_stalled = options.whole_fleet_ends_when_stalled;
  return s;
}

}  // namespace

LayeredResult planLayered(const GridMap& map, const Instance& instance, const FleetGraphs& graphs,
                          const LayeredOptions& options, const Deadline& deadline) {
  LayeredResult result;
  // Unknown backends throw InvalidInput before any work. A parallel fallback of a serial backend
  // answers InvalidInput at once around the chain's timed paths; solveByBackend() then plans
  // the level with those robots at their targets and delays it.
  makeSolver(options.backend, options.backend_parameters);
  if (!options.fallback.empty()) makeSolver(options.fallback, options.backend_parameters);
  const int n = static_cast<int>(instance.robots.size());

  // 1. Decomposition. It needs every robot to reach its target alone: an instance that fails the
  // pre-check is INFEASIBLE, as the backends report it in raw mode.
  auto t = std::chrono::steady_clock::now();
  if (options.decompose && n > 0 && options.precheck) {
    const SolvabilityReport report = checkSolvability(instance, graphs, deadline);
    if (!report.solvable()) {
      result.status = SolveStatus::Infeasible;
      result.reason = report.problems.front().reason;
      if (report.problems.size() > 1) result.reason += " (and " + std::to_string(report.problems.size() - 1) + " more)";
      result.decompose_s = since(t);
      return result;
    }
  }
  std::vector<SolvedSubproblem> order =
      decomposeInto(instance, graphs, options, deadline, result.decomposition, result.solved_as_one);
  result.decompose_s = since(t);

  // 2. Solve; 3. merge.
  t = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < order.size(); ++k) {
    order[k].seed_offset = k;
    if (!options.independent_clusters) order[k].cluster = 0;  // one chain (reported as such)
  }
  const SubproblemSolvingOptions solving_options = solvingOptions(options, result.decomposition);
  // Merging a large plan takes seconds (300 robots, 4,000 steps: 2-3.5 s): keep them back.
  const TimeBudget& budget = options.budget;
  const Deadline solving = deadline.within(
      deadline.remaining() - std::min(budget.merge_reserve_max_s, budget.merge_reserve_share * deadline.remaining()));
  SubproblemSolving solved = solveSubproblems(instance, graphs, std::move(order), solving_options, solving);
  result.solve_s = since(t);
  result.subproblems = std::move(solved.order);
  result.merges = std::move(solved.merges);
  result.step_asides = std::move(solved.step_asides);
  if (solved.status != SolveStatus::Success) {
    result.status = solved.status;
    result.reason = std::move(solved.reason);
    return result;
  }
  std::vector<Path> paths = std::move(solved.paths);
  // Improving the plan is optional work: it stops early, so that the final validation ends
  // within the deadline too (about 1 s for 300 robots, 4,000 steps).
  const Deadline polish =
      deadline.within(deadline.remaining() - std::min(budget.validation_reserve_s, 0.5 * deadline.remaining()));
  if (options.compress && options.refine) result.compression = compressPlan(instance, graphs, paths, polish);
  if (options.refine) result.refinement = refinePlan(instance, graphs, paths, polish);
  if (options.compress) {
    const CompressionStats again = compressPlan(instance, graphs, paths, polish);
    result.compression.passes += again.passes;
    result.compression.waits_removed += again.waits_removed;
    result.compression.time_s += again.time_s;
    result.compression.deadline_hit = again.deadline_hit;
  }
  result.plan.paths = std::move(paths);

  const ActionModel model = n > 0 ? graphs.graph(0).actionModel() : ActionModel{};
  const ValidationResult check = validatePlan(map, instance, result.plan, model);
  if (!check.valid()) {
    result.status = SolveStatus::InternalError;
    result.reason = "internal error: the merged plan fails validation: " + check.violation.message;
    return result;
  }
  std::vector<GridPose> targets;
  for (const auto& r : instance.robots) targets.push_back(r.target);
  result.metrics = planMetrics(result.plan, targets);
  result.status = SolveStatus::Success;
  return result;
}

}  // namespace fleet_planner
