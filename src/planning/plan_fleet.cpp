// The planning facade; see plan_fleet.h.
#include "fleet_planner/planning/plan_fleet.h"

#include <cmath>
#include <memory>

#include "../runtime/number_format.h"
#include "fleet_planner/execution/earliest_schedule.h"
#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/model/robot_cells.h"
#include "fleet_planner/planning/cell_steps.h"
#include "fleet_planner/planning/lattice.h"
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

std::string precheckReason(const SolvabilityReport& report) {
  const auto& found = report.problems;
  std::string reason = found.front().reason;
  if (found.size() > 1) reason += " (and " + std::to_string(found.size() - 1) + " more)";
  return reason;
}

/// One call on one lattice step. Returns false when the fleet is to be planned again on a finer
/// lattice (the reason is in result.lattice_notes); true when `result` is the answer.
class LatticeAttempt {
 public:
  /// second_chance_step: the step on which a stalled whole fleet ends early, since a coarser
  /// lattice follows it (0: none).
  LatticeAttempt(const GridMap& map, const Instance& instance, const PlanningOptions& options,
                 const PlanningCall& call, const Deadline& deadline, const MemoryGuard& memory,
                 PlanningResult& result, int second_chance_step = 0)
      : map_(map), instance_(instance), options_(options), call_(call), deadline_(deadline), memory_(memory),
        result_(result), second_chance_step_(second_chance_step) {}

  bool run(int step) {
    ActionModel model = options_.model;
    model.step = step;
    const auto graphs = buildGraphs(model);
    if (!graphs) return true;  // TIMEOUT or RESOURCE_LIMIT while building them
    graphs_ = graphs;
    // Step 1 with every start and target on a grid heading is the paper's model: no connections.
    bool yaws = false;
    for (const Robot& r : instance_.robots) yaws = yaws || r.start_yaw || r.target_yaw;
    if (step == 1 && !yaws) return planOn(instance_, *graphs, nullptr, 1);
    const LatticeInstance lattice = connectToLattice(map_, instance_, *graphs, step, result_.threads);
    if (!lattice.problems.empty()) {  // no lattice can help: a start or target that cannot turn
      result_.precheck.problems = lattice.problems;
      return finalFailure(SolveStatus::InvalidInput, precheckReason(result_.precheck));
    }
    if (!lattice.problem.empty()) return step > 1 ? giveUp(step, lattice.problem) : finalFailure(SolveStatus::Infeasible, lattice.problem);
    return planOn(lattice.instance, *graphs, &lattice, step);
  }

  /// The graphs of the last lattice tried.
  const std::shared_ptr<const FleetGraphs>& graphs() const { return graphs_; }

 private:
  std::shared_ptr<const FleetGraphs> buildGraphs(const ActionModel& model) {
    std::vector<Footprint> footprints;
    for (const Robot& r : instance_.robots) footprints.push_back(r.footprint);
    const auto t = std::chrono::steady_clock::now();
    std::shared_ptr<const FleetGraphs> graphs;
    bool cached = false;
    try {
      if (call_.cache != nullptr) {
        graphs = call_.cache->get(map_, call_.map_version, footprints, model, result_.threads, options_.limits,
                                  deadline_, cached);
      } else {
        graphs = std::make_shared<const FleetGraphs>(map_, footprints, model, result_.threads, options_.limits,
                                                     deadline_);
      }
    } catch (const DeadlineExpired& e) {
      result_.status = deadline_.outOfMemory() ? SolveStatus::ResourceLimit
                       : deadline_.cancelled() ? SolveStatus::Cancelled
                                               : SolveStatus::Timeout;
      result_.reason = deadline_.outOfMemory() ? memory_.reason() : e.what();
    }
    result_.graphs_cached = cached;
    result_.precompute_s += cached ? 0.0 : since(t);
    return graphs;
  }

  bool finalFailure(SolveStatus status, const std::string& why) {
    result_.status = status;
    result_.reason = why;
    return true;
  }

  bool giveUp(int step, const std::string& why) {
    result_.lattice_notes.push_back("step " + std::to_string(step) + ": " + why);
    return false;
  }

  // Plans `planned` (the instance itself, or its robots on the lattice) and, on a lattice, adds
  // the connections and validates the whole plan on the map's cells.
  bool planOn(const Instance& planned, const FleetGraphs& graphs, const LatticeInstance* lattice, int step) {
    const auto t_check = std::chrono::steady_clock::now();
    SolvabilityReport precheck = checkSolvability(planned, graphs, deadline_);
    if (!precheck.solvable()) {
      if (lattice && step > 1) return giveUp(step, precheckReason(precheck));
      result_.precheck = std::move(precheck);
      result_.status = SolveStatus::Infeasible;
      result_.reason = precheckReason(result_.precheck);
      result_.decompose_s = since(t_check);
      return true;
    }
    std::vector<std::string> notes = std::move(result_.lattice_notes);
    const double precompute_s = result_.precompute_s;
    const bool cached = result_.graphs_cached;
    LayeredOptions layered = layeredOptions(options_, result_.threads);
    layered.whole_fleet_ends_when_stalled = step == second_chance_step_;
    static_cast<LayeredResult&>(result_) = planLayered(map_, planned, graphs, layered, deadline_);
    result_.lattice_notes = std::move(notes);
    result_.precompute_s = precompute_s;
    result_.graphs_cached = cached;
    result_.lattice_step = step;
    if (!lattice) return true;
    if (result_.status == SolveStatus::Infeasible && step > 1) {
      return giveUp(step, "no plan on this lattice: " + result_.reason);
    }
    if (!result_.success()) return true;
    std::string problem;
    std::optional<Plan> full = assembleLatticePlan(instance_, *lattice, graphs, result_.plan, problem);
    if (!full) return step > 1 ? giveUp(step, problem) : finalFailure(SolveStatus::Infeasible, problem);
    result_.plan = std::move(*full);
    const bool on_cells = options_.cell_steps && step > 1;
    if (options_.compress && !on_cells && !deadline_.expired()) {
      // The connections were placed one robot after another, each start padded to the longest:
      // retimed as a whole, robots leave as soon as the others allow (on cell steps, there).
      const auto t_retime = std::chrono::steady_clock::now();
      result_.compression.waits_removed +=
          retimeToEarliest(instance_, result_.plan, graphs.graph(0).actionModel());
      result_.compression.time_s += since(t_retime);
    }
    result_.plan_step = step;
    // On cell steps the validator checks the plan returned; on the lattice's steps, this one.
    if (!(on_cells && !deadline_.expired() && timeOnCells(graphs.graph(0).actionModel()))) {
      const ValidationResult check = validatePlan(map_, instance_, result_.plan, graphs.graph(0).actionModel());
      if (!check.valid()) {
        result_.status = SolveStatus::InternalError;
        result_.reason = "internal error: the plan with its lattice connections fails validation: " +
                         check.violation.message;
        return true;
      }
    }
    result_.metrics = planMetrics(result_.plan, planTargets(instance_, result_.plan));
    return true;
  }

  // Puts the plan on steps of one cell (cell_steps.h), retimed so that the waits and turns the
  // lattice stretched to a move's time take their own, if the validator accepts it that way.
  // False (a note said, the plan left on the lattice's steps) if it does not, which is never
  // expected.
  bool timeOnCells(const ActionModel& lattice_model) {
    const auto t = std::chrono::steady_clock::now();
    Plan fine = onCellSteps(result_.plan, lattice_model);
    ActionModel cell_model = lattice_model;
    cell_model.step = 1;
    if (options_.compress) result_.cell_steps_saved = retimeToEarliest(instance_, fine, cell_model);
    const ValidationResult check = validatePlan(map_, instance_, fine, cell_model);
    result_.cell_steps_s = since(t);
    if (!check.valid()) {
      result_.cell_steps_saved = 0;
      result_.lattice_notes.push_back("internal error: the plan on cell steps fails validation (" +
                                      check.violation.message + "); returned on the lattice's steps");
      return false;
    }
    result_.plan = std::move(fine);
    result_.plan_step = 1;
    return true;
  }

  const GridMap& map_;
  const Instance& instance_;
  const PlanningOptions& options_;
  const PlanningCall& call_;
  const Deadline& deadline_;
  const MemoryGuard& memory_;
  PlanningResult& result_;
  const int second_chance_step_;
  std::shared_ptr<const FleetGraphs> graphs_;
};

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
  // On the default lattice of a step above 1, a share of the time; a fleet that times out there
  // is planned again on a lattice twice as coarse in the rest: other rows and columns and fewer
  // states, where a knot of a few large robots in an aisle that the finer lattice's searches
  // did not untie may come apart. A fleet solved as one subproblem ends there as soon as its
  // search stalls, so that the coarser lattice gets the time. Its answer is kept if it is a
  // plan (or an internal error); otherwise the first answer stands, with a note.
  const int first = initialLatticeStep(options, instance);
  const bool second_chance =
      options.lattice_step <= 0 && first > 1 && options.budget.default_lattice_share < 1.0;
  const Deadline first_deadline =
      second_chance ? deadline.within(deadline.remaining() * options.budget.default_lattice_share)
                    : deadline;
  LatticeAttempt attempt(map, instance, options, call, first_deadline, memory, result, second_chance ? first : 0);
  int step = first;
  while (!attempt.run(step) && step > 1) step = std::max(1, step / 2);
  std::shared_ptr<const FleetGraphs> graphs = attempt.graphs();
  if (second_chance && step == first && result.status == SolveStatus::Timeout &&
      !deadline.expired()) {
    const int coarser = 2 * first;
    PlanningResult again;
    again.backend = result.backend;
    again.fallback = result.fallback;
    again.threads = result.threads;
    again.layered = result.layered;
    const std::string timed_out = "step " + std::to_string(first) + ": timed out after " +
                                  io::formatNumber(std::round(since(call.started) * 10) / 10) +
                                  " s (" + result.reason + ")";
    LatticeAttempt second(map, instance, options, call, deadline, memory, again);
    const bool answered = second.run(coarser);
    if (answered && (again.success() || again.status == SolveStatus::InternalError)) {
      again.lattice_notes.insert(again.lattice_notes.begin(), result.lattice_notes.begin(),
                                 result.lattice_notes.end());
      again.lattice_notes.push_back(timed_out + "; planned on step " + std::to_string(coarser));
      again.precompute_s += result.precompute_s;
      result = std::move(again);
      graphs = second.graphs();
    } else {
      std::string why = answered ? std::string(statusName(again.status)) + ": " + again.reason
                                 : again.lattice_notes.back();
      const std::string prefix = "step " + std::to_string(coarser) + ": ";
      if (why.rfind(prefix, 0) == 0) why = why.substr(prefix.size());
      result.lattice_notes.push_back(timed_out + "; step " + std::to_string(coarser) +
                                     " tried in the rest of the time: " + why);
    }
  }
  if (result.success()) result.graphs = graphs;
  result.time_s = since(call.started);
  return result;
}

}  // namespace fleet_planner
