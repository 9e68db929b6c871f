// `solve`: plan an instance with a backend, raw (the fleet as one subproblem) or layered.
#include <chrono>
#include <memory>

#include "cli_common.h"
#include "fleet_planner/core/fleet_graphs.h"
#include "fleet_planner/core/memory_guard.h"
#include "fleet_planner/core/plan_io.h"
#include "fleet_planner/core/plan_validator.h"
#include "fleet_planner/layered_planner.h"

namespace fleet_planner::cli {

namespace {

int solvedByFallback(const LayeredResult& result) {
  int count = 0;
  for (const auto& s : result.subproblems) count += s.by_fallback ? 1 : 0;
  return count;
}

}  // namespace

void addSolveCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("solve", "plan an instance; print one JSON line");
  struct Options {
    ProblemOptions problem;
    std::string backend = "la_cbs";
    std::string mode = "raw";
    std::string steps = "1234";
    double time_limit = 60;
    std::uint64_t seed = 0;
    std::string out;
    int threads = defaultThreads();
    bool details = false;
    bool no_compress = false;
    bool no_refine = false;
    bool one_chain = false;
    std::string fallback;
  };
  auto o = std::make_shared<Options>();
  addProblemOptions(cmd, o->problem);
  addLimitOptions(cmd, o->problem.limits);
  cmd->add_option("--backend", o->backend, "la_cbs | la_lacam | la_lns (any registered backend)");
  cmd->add_option("--mode", o->mode, "raw: the fleet as one subproblem; layered: decompose first")
      ->check(CLI::IsMember({"raw", "layered"}));
  cmd->add_option("--steps", o->steps, "layered: decomposition steps 1, 12, 123 or 1234")
      ->check(CLI::IsMember({"1", "12", "123", "1234"}));
  cmd->add_option("--time-limit", o->time_limit, "seconds for the whole solve, graphs included")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", o->seed, "random seed (same seed, same plan)");
  cmd->add_option("--out", o->out, "write the plan (YAML) here on success");
  cmd->add_option("--threads", o->threads, "threads for graphs, relation graphs and subproblems (default: cores)")->check(CLI::PositiveNumber);
  cmd->add_flag("--no-compress", o->no_compress, "keep the merged plan's waits (no plan compression)");
  cmd->add_flag("--no-refine", o->no_refine, "keep the merged paths (no replanning of single robots)");
  cmd->add_flag("--one-chain", o->one_chain,
                "serial backends: plan every level around all earlier paths (no independent clusters)");
  cmd->add_option("--fallback", o->fallback,
                  "layered: backend tried on a subproblem that --backend fails, in the second half of its time "
                  "share, before the safeguard merges it (e.g. la_lns; default none)");
  cmd->add_flag("--details", o->details, "add the solved subproblems (robot ids, status, time, delay) to the JSON");
  cmd->callback([o] {
    const auto t0 = std::chrono::steady_clock::now();
    const MemoryGuard memory(o->problem.limits.max_memory_mb);
    const Deadline deadline = Deadline::in(o->time_limit).withMemoryGuard(&memory);
    const Problem p = loadProblem(o->problem);
    std::vector<Footprint> footprints;
    for (const auto& r : p.instance.robots) footprints.push_back(r.footprint);
    const auto t1 = std::chrono::steady_clock::now();
    // The graphs count against the time limit: a deadline that passes while they are built is a
    // TIMEOUT like any other.
    std::unique_ptr<FleetGraphs> graphs;
    LayeredResult result;
    try {
      graphs = std::make_unique<FleetGraphs>(p.map, footprints, ActionModel{}, o->threads, o->problem.limits, deadline);
    } catch (const DeadlineExpired& e) {
      result.status = deadline.outOfMemory() ? SolveStatus::ResourceLimit
                      : deadline.cancelled() ? SolveStatus::Cancelled
                                             : SolveStatus::Timeout;
      result.reason = deadline.outOfMemory() ? memory.reason() : e.what();
    }
    const double precompute_s = secondsSince(t1);

    LayeredOptions options;
    options.backend = o->backend;
    options.decompose = o->mode == "layered";
    options.last_step = static_cast<int>(o->steps.size());
    options.threads = o->threads;
    options.seed = o->seed;
    options.compress = !o->no_compress;
    options.refine = !o->no_refine;
    options.independent_clusters = !o->one_chain;
    options.fallback = o->fallback;
    if (graphs) result = planLayered(p.map, p.instance, *graphs, options, deadline);

    const int n = static_cast<int>(p.instance.robots.size());
    int largest = 0;
    for (const auto& s : result.subproblems) largest = std::max(largest, static_cast<int>(s.robots.size()));
    nlohmann::json j{{"status", statusName(result.status)},
                     {"success", result.success()},
                     {"backend", o->backend},
                     {"fallback", o->fallback},
                     {"mode", o->mode},
                     {"steps", options.decompose ? o->steps : ""},
                     {"agents", n},
                     {"seed", o->seed},
                     {"precompute_s", precompute_s},
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
                     {"solved_by_fallback", solvedByFallback(result)},
                     {"refine_s", result.refinement.time_s},
                     {"refine_searches", result.refinement.searches},
                     {"refine_improved", result.refinement.improved},
                     {"refine_expansions", result.refinement.expansions},
                     {"refine_group_searches", result.refinement.group_searches},
                     {"refine_soc_saved", result.refinement.soc_saved},
                     {"compress_s", result.compression.time_s},
                     {"waits_removed", result.compression.waits_removed}};
    if (o->details) {
      nlohmann::json list = nlohmann::json::array();
      for (const auto& s : result.subproblems) {
        nlohmann::json ids = nlohmann::json::array();
        for (int r : s.robots) ids.push_back(p.instance.robots[r].id);
        nlohmann::json aside = nlohmann::json::array();
        for (int r : s.stepping_aside) aside.push_back(p.instance.robots[r].id);
        list.push_back({{"robots", ids}, {"cluster", s.cluster}, {"level", s.level}, {"status", statusName(s.status)},
                        {"time_s", s.time_s}, {"delay", s.delay}, {"high_level_nodes", s.stats.high_level_nodes},
                        {"low_level_expansions", s.stats.low_level_expansions}, {"by_fallback", s.by_fallback}, {"stepping_aside", aside}});
      }
      j["subproblem_details"] = list;
    }
    if (result.success()) {
      j["soc"] = result.metrics.soc;
      j["makespan"] = result.metrics.makespan;
      if (!o->out.empty()) savePlan(p.instance, result.plan, o->out);
    } else {
      j["soc"] = nullptr;
      j["makespan"] = nullptr;
      j["reason"] = result.reason;
    }
    j["time_s"] = secondsSince(t0);
    j["peak_rss_mb"] = peakRssMb();
    // The CLI's own check of the returned plan, outside the timing: true only for a plan that the
    // independent validator accepts (the planner validates too; this records it per run).
    j["valid"] = result.success() && validatePlan(p.map, p.instance, result.plan).valid();
    printJsonLine(j);
  });
}

}  // namespace fleet_planner::cli
