// Solving and merging the subproblems: the loop; see subproblem_solving.h and solving.h.
#include "fleet_planner/layered/subproblem_solving.h"

#include "fleet_planner/solvers/registry.h"
#include "solving.h"

namespace fleet_planner {

std::string idsOf(const Instance& instance, const std::vector<int>& robots) {
  std::string out;
  for (std::size_t k = 0; k < robots.size() && k < 6; ++k) out += (k ? "," : "") + instance.robots[robots[k]].id;
  if (robots.size() > 6) out += ",... (" + std::to_string(robots.size()) + " robots)";
  return out;
}

Solving::Solving(const Instance& instance, const FleetGraphs& graphs, const SubproblemSolvingOptions& options,
        const Deadline& deadline)
    : instance_(instance), graphs_(graphs), options_(options), deadline_(deadline),
      serial_(makeSolver(options.backend, options.backend_parameters)->avoidsMovingObstacles()) {}

SubproblemSolving Solving::run(std::vector<SolvedSubproblem> order) {
  SubproblemSolving out;
  order_ = std::move(order);
  results_.assign(order_.size(), std::nullopt);
  if (std::optional<std::string> proof = entangledPairProof()) {
    out.status = SolveStatus::Infeasible;
    out.reason = *proof + "; found before solving";
    out.order = order_;
    return out;
  }
  for (;;) {
    solvePending();
    std::size_t k = 0;
    while (k < order_.size() && results_[k] && results_[k]->success()) ++k;
    if (k == order_.size()) break;
    const SolveResult failed = results_[k] ? *results_[k] : SolveResult{};
    if (deadline_.expired() || order_.size() == 1) {
      out.status = deadline_.outOfMemory() ? SolveStatus::ResourceLimit
                   : deadline_.cancelled() ? SolveStatus::Cancelled
                   : deadline_.expired()   ? SolveStatus::Timeout
                                           : failed.status;
      out.reason = "subproblem " + std::to_string(k) + " (" + idsOf(instance_, order_[k].robots) + "): " +
                   (results_[k] ? failed.reason : std::string("not solved"));
      out.order = order_;
      out.merges = merges_;
      out.step_asides = step_asides_;
      return out;
    }
    if (std::optional<std::string> proof = infeasiblePairIn(k)) {
      out.status = SolveStatus::Infeasible;
      out.reason = *proof + "; found after subproblem " + std::to_string(k) + " (" + idsOf(instance_, order_[k].robots) +
                   ") failed: " + (results_[k] ? failed.reason : std::string("not solved"));
      out.order = order_;
      out.merges = merges_;
      out.step_asides = step_asides_;
      return out;
    }
    if (!order_[k].step_aside_tried && letStepAside(k, failed)) continue;
    mergeWithNeighbour(k, failed);
  }
  out.paths = mergePlans();
  out.order = order_;
  out.merges = merges_;
  out.step_asides = step_asides_;
  return out;
}

SubproblemSolving solveSubproblems(const Instance& instance, const FleetGraphs& graphs,
                                   std::vector<SolvedSubproblem> order, const SubproblemSolvingOptions& options,
                                   const Deadline& deadline) {
  return Solving(instance, graphs, options, deadline).run(std::move(order));
}

}  // namespace fleet_planner
