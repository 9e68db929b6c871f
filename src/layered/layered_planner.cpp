// Layered LA-MAPF: paper, Algorithms 5 and 6; see layered_planner.h.
#include "fleet_planner/layered_planner.h"

#include <algorithm>
#include <chrono>

#include "fleet_planner/core/errors.h"
#include "fleet_planner/core/instance_check.h"
#include "fleet_planner/core/plan_validator.h"
#include "fleet_planner/solvers/registry.h"

namespace fleet_planner {

namespace {

// Seconds kept back from plan refinement and compression for the final validation.
constexpr double kValidationReserveS = 1.0;
// Part of the time left (and at most how many seconds) that solving the subproblems leaves to
// merging their plans (Algorithm 5) and validating the result: on Berlin_1_256 with 300 robots,
// a level solved 0.2-2.7 s before the deadline was merged in 2.1-3.5 s and answered at 60.5-61.9 s.
constexpr double kMergeReserveShare = 0.1;
constexpr double kMergeReserveMaxS = 3.0;

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

LayeredResult planLayered(const GridMap& map, const Instance& instance, const FleetGraphs& graphs,
                          const LayeredOptions& options, const Deadline& deadline) {
  LayeredResult result;
  // Unknown backends throw InvalidInput before any work.
  const bool serial = makeSolver(options.backend)->avoidsMovingObstacles();
  if (!options.fallback.empty() && serial && !makeSolver(options.fallback)->avoidsMovingObstacles()) {
    throw InvalidInput("fallback backend '" + options.fallback + "' cannot plan around moving obstacles, which " +
                       "backend '" + options.backend + "' hands on");
  }
  const int n = static_cast<int>(instance.robots.size());

  // 1. Decomposition. It needs every robot to reach its target alone: an instance that fails the
  // pre-check is INFEASIBLE, as the backends report it in raw mode.
  std::vector<SolvedSubproblem> order;
  auto t = std::chrono::steady_clock::now();
  if (options.decompose && n > 0) {
    const SolvabilityReport report = checkSolvability(instance, graphs, deadline);
    if (!report.solvable()) {
      result.status = SolveStatus::Infeasible;
      result.reason = report.problems.front().reason;
      if (report.problems.size() > 1) result.reason += " (and " + std::to_string(report.problems.size() - 1) + " more)";
      result.decompose_s = since(t);
      return result;
    }
    DecompositionOptions d;
    d.last_step = options.last_step;
    d.threads = options.threads;
    // At most half of the time: a decomposition cut short is still legal (coarser), and the
    // subproblems need time too.
    result.decomposition = decompose(instance, graphs, d, deadline.within(deadline.remaining() * 0.5));
    for (const auto& s : result.decomposition.subproblems) {
      SolvedSubproblem solved;
      solved.robots = s.robots;
      solved.cluster = s.cluster;
      solved.level = s.level;
      order.push_back(solved);
    }
  } else {
    SolvedSubproblem all;
    for (int i = 0; i < n; ++i) all.robots.push_back(i);
    order.push_back(all);
    DecompositionSubproblem whole;
    whole.robots = all.robots;
    result.decomposition.subproblems.push_back(whole);
  }
  result.decompose_s = since(t);

  // 2. Solve; 3. merge.
  t = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < order.size(); ++k) {
    order[k].seed_offset = k;
    if (!options.independent_clusters) order[k].cluster = 0;  // one chain (reported as such)
  }
  SubproblemSolvingOptions solving_options;
  solving_options.backend = options.backend;
  solving_options.fallback = options.fallback;
  solving_options.threads = options.threads;
  solving_options.seed = options.seed;
  solving_options.entangled_pairs = result.decomposition.entangled_pairs;
  solving_options.entangled_known = options.decompose && result.decomposition.pairs_complete;
  const Deadline solving =
      deadline.within(deadline.remaining() - std::min(kMergeReserveMaxS, kMergeReserveShare * deadline.remaining()));
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
  // Improving the plan is optional work: it stops 1 s (at most half the time left) early, so that
  // the final validation ends within the deadline too (about 1 s for 300 robots, 4,000 steps).
  const Deadline polish = deadline.within(deadline.remaining() - std::min(kValidationReserveS, 0.5 * deadline.remaining()));
  if (options.refine) result.refinement = refinePlan(instance, graphs, paths, polish);
  if (options.compress) result.compression = compressPlan(graphs, paths, polish);
  result.plan.paths = std::move(paths);

  const ActionModel model = n > 0 ? graphs.graph(0).actionModel() : ActionModel{};
  const ValidationResult check = validatePlan(map, instance, result.plan, model);
  if (!check.valid()) {
    result.status = SolveStatus::Infeasible;
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
