// Layered LA-MAPF: paper, Algorithms 5 and 6; see layered_planner.h.
#include "fleet_planner/layered_planner.h"

#include <algorithm>
#include <chrono>

#include "fleet_planner/core/errors.h"
#include "fleet_planner/core/instance_check.h"
#include "fleet_planner/core/plan_validator.h"
#include "fleet_planner/layered/plan_merge.h"
#include "fleet_planner/solvers/registry.h"

namespace fleet_planner {

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::string idsOf(const Instance& instance, const std::vector<int>& robots) {
  std::string out;
  for (std::size_t k = 0; k < robots.size() && k < 6; ++k) out += (k ? "," : "") + instance.robots[robots[k]].id;
  if (robots.size() > 6) out += ",... (" + std::to_string(robots.size()) + " robots)";
  return out;
}

}  // namespace

LayeredResult planLayered(const GridMap& map, const Instance& instance, const FleetGraphs& graphs,
                          const LayeredOptions& options, const Deadline& deadline) {
  LayeredResult result;
  auto solver = makeSolver(options.backend);
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
    result.decomposition = decompose(instance, graphs, d, deadline);
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

  // 2. Solve in order; 3. merge as we go.
  t = std::chrono::steady_clock::now();
  std::vector<Path> paths(n);
  std::vector<char> done(n, 0);
  const bool serial = solver->avoidsMovingObstacles();
  int robots_left = n;
  for (std::size_t k = 0; k < order.size();) {
    Subproblem sub;
    sub.instance = &instance;
    sub.graphs = &graphs;
    sub.robots = order[k].robots;
    // A time share: at least a quarter of what is left, more for a larger part of the robots
    // left; the last subproblem gets all of it. A share that runs out triggers the safeguard.
    const double share = k + 1 == order.size()
                             ? 1.0
                             : std::max(0.25, static_cast<double>(sub.robots.size()) / std::max(1, robots_left));
    sub.deadline = deadline.within(deadline.remaining() * share);
    sub.seed = options.seed + k;
    for (std::size_t m = k + 1; m < order.size(); ++m) {
      for (int r : order[m].robots) sub.blocked.push_back({r, instance.robots[r].start});
    }
    for (int r = 0; r < n; ++r) {
      if (!done[r]) continue;
      if (serial) {
        sub.moving.push_back({r, paths[r]});
      } else {
        sub.blocked.push_back({r, instance.robots[r].target});
      }
    }
    const SolveResult solved = solver->solve(sub);
    order[k].status = solved.status;
    order[k].reason = solved.reason;
    order[k].time_s = solved.stats.time_s;
    order[k].stats = solved.stats;
    if (solved.success()) {
      std::vector<Path> fresh = solved.paths;
      if (!serial) order[k].delay = delayToFit(graphs, paths, done, sub.robots, fresh);
      for (std::size_t a = 0; a < sub.robots.size(); ++a) {
        paths[sub.robots[a]] = std::move(fresh[a]);
        done[sub.robots[a]] = 1;
      }
      robots_left -= static_cast<int>(sub.robots.size());
      ++k;
      continue;
    }
    const bool out_of_time = deadline.expired();
    if (out_of_time || order.size() == 1) {
      result.status = out_of_time && !deadline.cancelled() ? SolveStatus::Timeout : solved.status;
      if (deadline.cancelled()) result.status = SolveStatus::Cancelled;
      if (deadline.outOfMemory()) result.status = SolveStatus::ResourceLimit;
      result.reason = "subproblem " + std::to_string(k) + " (" + idsOf(instance, order[k].robots) + "): " + solved.reason;
      result.subproblems = order;
      result.solve_s = since(t);
      return result;
    }
    // Safeguard: merge with the next subproblem (or, for the last, with the one before, whose
    // paths are dropped) and solve again.
    const std::size_t other = k + 1 < order.size() ? k + 1 : k - 1;
    const std::size_t first = std::min(k, other);
    result.merges.push_back("subproblem " + std::to_string(k) + " (" + idsOf(instance, order[k].robots) + ") failed: " +
                            solved.reason + " (after " + std::to_string(solved.stats.time_s).substr(0, 5) + " s, " +
                            std::to_string(solved.stats.high_level_nodes) + " high-level nodes, " +
                            std::to_string(solved.stats.low_level_expansions) + " expansions); merged with subproblem " +
                            std::to_string(other));
    for (int r : order[first].robots) {
      if (done[r]) ++robots_left;
      done[r] = 0;
    }
    std::vector<int> joined = order[first].robots;
    joined.insert(joined.end(), order[first + 1].robots.begin(), order[first + 1].robots.end());
    std::sort(joined.begin(), joined.end());
    order[first].robots = joined;
    order.erase(order.begin() + static_cast<std::ptrdiff_t>(first) + 1);
    k = first;
  }
  result.solve_s = since(t);
  result.subproblems = order;
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
