// `solve`: plan an instance with a backend (raw mode: the whole fleet as one subproblem).
#include <chrono>

#include "cli_common.h"
#include "fleet_planner/core/fleet_graphs.h"
#include "fleet_planner/core/plan_io.h"
#include "fleet_planner/core/plan_validator.h"
#include "fleet_planner/solvers/registry.h"

namespace fleet_planner::cli {

void addSolveCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("solve", "plan an instance; print one JSON line");
  struct Options {
    ProblemOptions problem;
    std::string backend = "la_cbs";
    std::string mode = "raw";
    double time_limit = 60;
    std::uint64_t seed = 0;
    std::string out;
    int threads = 1;
  };
  auto o = std::make_shared<Options>();
  addProblemOptions(cmd, o->problem);
  cmd->add_option("--backend", o->backend, "la_cbs | la_lacam (any registered backend)");
  cmd->add_option("--mode", o->mode, "raw: one subproblem for the whole fleet")->check(CLI::IsMember({"raw"}));
  cmd->add_option("--time-limit", o->time_limit, "seconds for the whole solve, graphs included")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", o->seed, "random seed (same seed, same plan)");
  cmd->add_option("--out", o->out, "write the plan (YAML) here on success");
  cmd->add_option("--threads", o->threads, "threads for graph building")->check(CLI::PositiveNumber);
  cmd->callback([o] {
    const auto t0 = std::chrono::steady_clock::now();
    const Deadline deadline = Deadline::in(o->time_limit);
    const Problem p = loadProblem(o->problem);
    auto solver = makeSolver(o->backend);
    std::vector<Footprint> footprints;
    for (const auto& r : p.instance.robots) footprints.push_back(r.footprint);
    const auto t1 = std::chrono::steady_clock::now();
    const FleetGraphs graphs(p.map, footprints, {}, o->threads);
    const double precompute_s = secondsSince(t1);

    Subproblem sub;
    sub.instance = &p.instance;
    sub.graphs = &graphs;
    for (int i = 0; i < static_cast<int>(p.instance.robots.size()); ++i) sub.robots.push_back(i);
    sub.deadline = deadline;
    sub.seed = o->seed;
    const SolveResult result = solver->solve(sub);

    nlohmann::json j{{"status", statusName(result.status)},
                     {"success", result.success()},
                     {"backend", o->backend},
                     {"mode", o->mode},
                     {"agents", p.instance.robots.size()},
                     {"seed", o->seed},
                     {"precompute_s", precompute_s},
                     {"solve_s", result.stats.time_s},
                     {"high_level_nodes", result.stats.high_level_nodes},
                     {"low_level_expansions", result.stats.low_level_expansions}};
    if (result.success()) {
      Plan plan;
      plan.paths = result.paths;
      const ValidationResult v = validatePlan(p.map, p.instance, plan);
      std::vector<GridPose> targets;
      for (const auto& r : p.instance.robots) targets.push_back(r.target);
      const PlanMetrics m = planMetrics(plan, targets);
      j["valid"] = v.valid();
      if (!v.valid()) j["violation"] = v.violation.message;
      j["soc"] = m.soc;
      j["makespan"] = m.makespan;
      if (!o->out.empty()) savePlan(p.instance, plan, o->out);
      if (!v.valid()) setExitCode(1);
    } else {
      j["valid"] = false;
      j["soc"] = nullptr;
      j["makespan"] = nullptr;
      j["reason"] = result.reason;
    }
    j["time_s"] = secondsSince(t0);
    j["peak_rss_mb"] = peakRssMb();
    printJsonLine(j);
  });
}

}  // namespace fleet_planner::cli
