// `decompose`: run the decomposition (steps 1..4) and report it; one JSON line.
#include <chrono>

#include "cli_common.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/runtime/memory_guard.h"
#include "fleet_planner/decomposition/decomposition.h"
#include "fleet_planner/decomposition/legality.h"

namespace fleet_planner::cli {

void addDecomposeCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("decompose", "decompose an instance into clusters and levels; print one JSON line");
  struct Options {
    ProblemOptions problem;
    std::string steps = "1234";
    int threads = defaultThreads();
    bool check = false;
    bool list = false;
  };
  auto o = std::make_shared<Options>();
  addProblemOptions(cmd, o->problem);
  addLimitOptions(cmd, o->problem.limits);
  cmd->add_option("--steps", o->steps, "decomposition steps: 1, 12, 123 or 1234")
      ->check(CLI::IsMember({"1", "12", "123", "1234"}));
  cmd->add_option("--threads", o->threads, "threads for graphs and relation graphs")->check(CLI::PositiveNumber);
  cmd->add_flag("--check", o->check, "also run the independent legality checker");
  cmd->add_flag("--list", o->list, "list the subproblems' robot ids");
  cmd->callback([o] {
    const Problem p = loadProblem(o->problem);
    std::vector<Footprint> footprints;
    for (const auto& r : p.instance.robots) footprints.push_back(r.footprint);
    const auto t0 = std::chrono::steady_clock::now();
    const FleetGraphs graphs(p.map, footprints, {}, o->threads, o->problem.limits);
    const double precompute_s = secondsSince(t0);
    DecompositionOptions options;
    options.last_step = static_cast<int>(o->steps.size());
    options.threads = o->threads;
    const auto t1 = std::chrono::steady_clock::now();
    const MemoryGuard memory(o->problem.limits.max_memory_mb);
    const Decomposition d = decompose(p.instance, graphs, options, Deadline().withMemoryGuard(&memory));
    if (memory.exceeded()) throw ResourceLimitError("max_memory_mb", "decomposition stopped: " + memory.reason());
    const double decompose_s = secondsSince(t1);
    nlohmann::json steps = nlohmann::json::array();
    for (const auto& s : d.steps) {
      steps.push_back({{"step", s.step}, {"subproblems", s.subproblems}, {"largest", s.largest}, {"time_s", s.time_s}});
    }
    const int n = static_cast<int>(p.instance.robots.size());
    nlohmann::json j{{"agents", n},
                     {"steps", o->steps},
                     {"precompute_s", precompute_s},
                     {"relations_s", d.relations_s},
                     {"decompose_s", decompose_s},
                     {"subproblems", d.subproblems.size()},
                     {"max_subproblem", d.largest()},
                     {"decomposition_rate", d.rate(n)},
                     {"per_step", steps},
                     {"entangled_pairs", d.entangled_pairs.size()},
                     {"entangled_s", d.entangled_s},
                     {"peak_rss_mb", peakRssMb()}};
    if (o->list) {
      nlohmann::json list = nlohmann::json::array();
      for (const auto& s : d.subproblems) {
        nlohmann::json ids = nlohmann::json::array();
        for (int r : s.robots) ids.push_back(p.instance.robots[r].id);
        list.push_back({{"cluster", s.cluster}, {"level", s.level}, {"robots", ids}});
      }
      j["subproblem_list"] = list;
      nlohmann::json pairs = nlohmann::json::array();
      for (const auto& [a, b] : d.entangled_pairs) {
        pairs.push_back({p.instance.robots[a].id, p.instance.robots[b].id});
      }
      j["entangled_pair_list"] = pairs;
    }
    if (o->check) {
      std::vector<std::vector<int>> order;
      for (const auto& s : d.subproblems) order.push_back(s.robots);
      const LegalityReport legal = checkLegality(p.instance, graphs, order);
      j["legal"] = legal.legal;
      if (!legal.legal) {
        j["illegal"] = legal.message;
        setExitCode(1);
      }
    }
    printJsonLine(j);
  });
}

}  // namespace fleet_planner::cli
