// `generate`: a random instance with the paper's distribution, written as a YAML scenario.
#include <chrono>
#include <filesystem>

#include "cli_common.h"
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
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("--map", o->map, "map: MovingAI .map or map_server .yaml")->required();
  cmd->add_option("--agents", o->gen.robots, "number of robots")->required()->check(CLI::PositiveNumber);
  cmd->add_option("--seed", o->gen.seed, "random seed (same seed, same instance)");
  cmd->add_option("--out", o->out, "scenario file to write (.yaml)")->required();
  cmd->add_flag("--backward", o->backward, "graphs allow moving backward (for reachability)");
  cmd->callback([o] {
    namespace fs = std::filesystem;
    const auto t0 = std::chrono::steady_clock::now();
    const GridMap map = loadMap(o->map);
    o->gen.model.allow_backward = o->backward;
    Instance instance = generateInstance(map, o->gen);
    // The scenario names its map relative to its own folder.
    const fs::path out_dir = fs::absolute(o->out).parent_path();
    const std::string map_ref = fs::relative(fs::absolute(o->map), out_dir).generic_string();
    instance.map_file = map_ref;
    saveScenario(instance, o->out);
    printJsonLine({{"agents", instance.robots.size()},
                   {"seed", o->gen.seed},
                   {"out", o->out},
                   {"map", map_ref},
                   {"time_s", secondsSince(t0)}});
  });
}

}  // namespace fleet_planner::cli
