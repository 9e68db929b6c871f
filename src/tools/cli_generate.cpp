// `generate`: a random instance with the paper's distribution, written as a YAML scenario.
#include <chrono>
#include <filesystem>

#include "cli_common.h"
#include "fleet_planner/infeasibility/feasible_instances.h"
#include "fleet_planner/io/instance_generator.h"
#include "fleet_planner/io/instance_io.h"
#include "fleet_planner/io/map_io.h"

namespace fleet_planner::cli {

void addGenerateCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("generate", "random instance (paper's distribution) as a YAML scenario");
  struct Options {
    std::string map, out;
    GeneratorOptions gen;
    bool backward = false;
    bool feasible = false;
    int max_rounds = 10;
    double check_time = 300.0;
    long long pair_expansions = kGeneratorPairExpansions;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("--map", o->map, "map: MovingAI .map or map_server .yaml")->required();
  cmd->add_option("--agents", o->gen.robots, "number of robots")->required()->check(CLI::PositiveNumber);
  cmd->add_option("--seed", o->gen.seed, "random seed (same seed, same instance)");
  cmd->add_option("--out", o->out, "scenario file to write (.yaml)")->required();
  cmd->add_flag("--backward", o->backward, "graphs allow moving backward (for reachability)");
  cmd->add_flag("--feasible", o->feasible,
                "draw again the robots of pairs not shown able to reach both targets (the planner's pair proofs "
                "on the decomposition's entangled pairs: proven unable, or undecided), until every such pair is "
                "shown able; JSON lists them");
  cmd->add_option("--max-rounds", o->max_rounds, "--feasible: checks at most (default 10)")->check(CLI::PositiveNumber);
  cmd->add_option("--check-time-limit", o->check_time, "--feasible: seconds for the checks (default 300)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--sweep-tolerance", o->gen.check_sweep_tolerance,
                  "--feasible: the pairs are decided (and robots drawn again) with rotations that may clip this "
                  "many cells beyond their end poses, as `solve --sweep-tolerance` plans (default 0: exact sweep)")
      ->check(CLI::Range(0.0, Footprint::kMaxSweepTolerance));
  cmd->add_option("--pair-expansions", o->pair_expansions,
                  "--feasible: LA-LaCAM expansions of each pair proof (default 4000000)")
      ->check(CLI::PositiveNumber);
  cmd->callback([o] {
    namespace fs = std::filesystem;
    const auto t0 = std::chrono::steady_clock::now();
    const GridMap map = loadMap(o->map);
    o->gen.model.allow_backward = o->backward;
    FeasibleGeneration generated;
    if (o->feasible) {
      generated = generateFeasibleInstance(map, o->gen, o->max_rounds, o->pair_expansions,
                                           Deadline::in(o->check_time));
    } else {
      generated.instance = generateInstance(map, o->gen);
    }
    Instance& instance = generated.instance;
    // The scenario names its map relative to its own folder.
    const fs::path out_dir = fs::absolute(o->out).parent_path();
    const std::string map_ref = fs::relative(fs::absolute(o->map), out_dir).generic_string();
    instance.map_file = map_ref;
    saveScenario(instance, o->out);
    printJsonLine({{"agents", instance.robots.size()},
                   {"seed", o->gen.seed},
                   {"out", o->out},
                   {"map", map_ref},
                   {"time_s", secondsSince(t0)},
                   {"feasible_check", o->feasible},
                   {"check_rounds", generated.rounds},
                   {"check_clean", generated.clean},
                   {"redrawn", generated.redrawn}});
  });
}

}  // namespace fleet_planner::cli
