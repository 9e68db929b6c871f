// `solve`: plan an instance through the planning facade (plan_fleet.h), with the node's defaults.
#include <chrono>
#include <memory>

#include "cli_common.h"
#include "fleet_planner/io/plan_io.h"
#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/planning/plan_fleet.h"

namespace fleet_planner::cli {

namespace {

int solvedByFallback(const LayeredResult& result) {
  int count = 0;
  for (const auto& s : result.subproblems) count += s.by_fallback ? 1 : 0;
  return count;
}

nlohmann::json subproblemDetails(const Instance& instance, const LayeredResult& result) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& s : result.subproblems) {
    nlohmann::json ids = nlohmann::json::array();
    for (int r : s.robots) ids.push_back(instance.robots[r].id);
    nlohmann::json aside = nlohmann::json::array();
    for (int r : s.stepping_aside) aside.push_back(instance.robots[r].id);
    list.push_back({{"robots", ids}, {"cluster", s.cluster}, {"level", s.level}, {"status", statusName(s.status)},
                    {"time_s", s.time_s}, {"delay", s.delay}, {"high_level_nodes", s.stats.high_level_nodes},
                    {"low_level_expansions", s.stats.low_level_expansions},
                    {"lower_bound", s.stats.lower_bound}, {"stopped_early", s.stopped_early},
                    {"by_fallback", s.by_fallback},
                    {"stepping_aside", aside}});
  }
  return list;
}

nlohmann::json resultJson(const PlanningResult& result, const std::string& mode, const std::string& steps, int n,
                          std::uint64_t seed) {
  int largest = 0;
  for (const auto& s : result.subproblems) largest = std::max(largest, static_cast<int>(s.robots.size()));
  return {{"status", statusName(result.status)},
          {"success", result.success()},
          {"backend", result.backend},
          {"fallback", result.fallback},
          {"mode", mode},
          {"steps", mode == "layered" ? steps : ""},
          {"agents", n},
          {"seed", seed},
          {"threads", result.threads},
          {"lattice_step", result.lattice_step},
          {"plan_step", result.plan_step},
          {"lattice_notes", result.lattice_notes},
          {"precompute_s", result.precompute_s},
          {"decompose_s", result.decompose_s},
          {"solve_s", result.solve_s},
          {"subproblems", result.decomposition.subproblems.size()},
          {"max_subproblem", result.decomposition.largest()},
          {"decomposition_rate", result.decomposition.rate(n)},
          {"entangled_pairs", result.decomposition.entangled_pairs.size()},
          {"solved_subproblems", result.subproblems.size()},
          {"max_solved_subproblem", largest},
          {"merges", result.merges},
          {"step_asides", result.step_asides},
          {"solved_as_one", result.solved_as_one},
          {"solved_by_fallback", solvedByFallback(result)},
          {"refine_s", result.refinement.time_s},
          {"refine_searches", result.refinement.searches},
          {"refine_improved", result.refinement.improved},
          {"refine_expansions", result.refinement.expansions},
          {"refine_group_searches", result.refinement.group_searches},
          {"refine_soc_saved", result.refinement.soc_saved},
          {"compress_s", result.compression.time_s},
          {"waits_removed", result.compression.waits_removed},
          {"cell_steps_s", result.cell_steps_s},
          {"cell_steps_saved", result.cell_steps_saved}};
}

}  // namespace

void addSolveCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("solve", "plan an instance (the node's defaults); print one JSON line");
  struct Options {
    ProblemOptions problem;
    PlanningOptions planning;
    std::string mode = "layered";
    std::string steps = "1234";
    std::string out;
    bool details = false;
    bool no_compress = false;
    bool lattice_timing = false;
    bool no_refine = false;
    bool one_chain = false;
    bool backward = false;
    bool forward_only = false;
    std::vector<std::string> backend_params;
  };
  auto o = std::make_shared<Options>();
  addProblemOptions(cmd, o->problem);
  addLimitOptions(cmd, o->problem.limits);
  addBackendOptions(cmd, o->planning, o->backend_params);
  cmd->add_option("--mode", o->mode, "layered: decompose first (default); raw: the fleet as one subproblem")
      ->check(CLI::IsMember({"raw", "layered"}));
  cmd->add_option("--steps", o->steps, "layered: decomposition steps 1, 12, 123 or 1234 (default)")
      ->check(CLI::IsMember({"1", "12", "123", "1234"}));
  cmd->add_option("--time-limit", o->planning.time_limit, "seconds for the whole solve, graphs included (default 10)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", o->planning.seed, "random seed (same seed, same plan)");
  cmd->add_option("--out", o->out, "write the plan (YAML) here on success");
  cmd->add_option("--threads", o->planning.threads,
                  "threads for graphs, relation graphs, subproblems and a whole fleet's two parking plans and "
                  "two LA-LNS searches; the plan is the same for any count from 2 on, and for 1 too unless a "
                  "fleet of 100 robots or more is solved as one subproblem (default 0: the machine's cores)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option(
         "--lattice-step", o->planning.lattice_step,
         "planning lattice: moves advance this many map cells (default 0: a third of the narrowest "
         "robot's width, at least 1; the benchmark pools plan at 1). A fleet that cannot be "
         "planned on it is planned on half the step; on the default, one that times out in two "
         "thirds of the time is planned on twice the step in the rest (lattice_notes says why)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--no-compress", o->no_compress, "keep the merged plan's waits (no plan compression)");
  cmd->add_flag("--lattice-timing", o->lattice_timing,
                "return a plan made on a lattice step above 1 on the lattice's steps (a move of up to that many "
                "cells a step) instead of steps of one cell");
  cmd->add_flag("--no-refine", o->no_refine, "keep the merged paths (no replanning of single robots)");
  cmd->add_flag("--one-chain", o->one_chain,
                "serial backends: plan every level around all earlier paths (no independent clusters)");
  auto* backward = cmd->add_flag(
      "--backward", o->backward,
      "robots may also move backward (the default on map_server maps, as the node plans: real robots reverse)");
  cmd->add_flag("--forward-only", o->forward_only,
                "robots only move forward and turn in place (the default on MovingAI maps: the paper's model)")
      ->excludes(backward);
  cmd->add_flag("--details", o->details, "add the solved subproblems (robot ids, status, time, delay) to the JSON");
  cmd->callback([o] {
    PlanningCall call;  // the time limit counts from here: loading the problem is part of it
    const Problem p = loadProblem(o->problem);
    PlanningOptions options = o->planning;
    applyBackendOptions(options, o->backend_params);
    options.decompose = o->mode == "layered";
    options.last_step = static_cast<int>(o->steps.size());
    options.compress = !o->no_compress;
    options.cell_steps = !o->lattice_timing;
    options.refine = !o->no_refine;
    options.independent_clusters = !o->one_chain;
    options.limits = o->problem.limits;
    options.model.allow_backward = o->backward || (!o->forward_only && p.map_server);
    const PlanningResult result = planFleet(p.map, p.instance, options, call);

    const int n = static_cast<int>(p.instance.robots.size());
    nlohmann::json j = resultJson(result, o->mode, o->steps, n, options.seed);
    j["backward"] = options.model.allow_backward;
    if (o->details) j["subproblem_details"] = subproblemDetails(p.instance, result);
    if (result.success()) {
      j["soc"] = result.metrics.soc;
      j["makespan"] = result.metrics.makespan;
      if (!o->out.empty()) savePlan(p.instance, result.plan, o->out, options.model.allow_backward);
    } else {
      j["soc"] = nullptr;
      j["makespan"] = nullptr;
      j["reason"] = result.reason;
    }
    j["time_s"] = secondsSince(call.started);
    j["peak_rss_mb"] = peakRssMb();
    // The CLI's own check of the returned plan, outside the timing: true only for a plan that the
    // independent validator accepts (the planner validates too; this records it per run).
    ActionModel model = options.model;
    model.step = result.plan_step;
    j["valid"] = result.success() && validatePlan(p.map, p.instance, result.plan, model).valid();
    printJsonLine(j);
    if (result.status == SolveStatus::InternalError) setExitCode(kExitInternalError);
  });
}

}  // namespace fleet_planner::cli
