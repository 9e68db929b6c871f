// `graphs`: build every robot's state graph and report size, time and memory.
#include <chrono>

#include "cli_common.h"
#include "fleet_planner/model/fleet_graphs.h"

namespace fleet_planner::cli {

void addGraphsCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("graphs", "build every robot's state graph; print one JSON line");
  auto options = std::make_shared<ProblemOptions>();
  auto threads = std::make_shared<int>(1);
  auto backward = std::make_shared<bool>(false);
  addProblemOptions(cmd, *options);
  addLimitOptions(cmd, options->limits);
  cmd->add_option("--threads", *threads, "threads for graph building")->check(CLI::PositiveNumber);
  cmd->add_flag("--backward", *backward, "allow moving one cell backward");
  cmd->callback([options, threads, backward] {
    const auto t0 = std::chrono::steady_clock::now();
    const Problem problem = loadProblem(*options);
    const double load_s = secondsSince(t0);
    std::vector<Footprint> footprints;
    for (const auto& r : problem.instance.robots) footprints.push_back(r.footprint);
    const auto t1 = std::chrono::steady_clock::now();
    ActionModel model;
    model.allow_backward = *backward;
    const FleetGraphs graphs(problem.map, footprints, model, *threads, options->limits);
    const double build_s = secondsSince(t1);
    long long edges = 0;
    for (int i = 0; i < graphs.numRobots(); ++i) edges += graphs.graph(i).numEdges();
    printJsonLine({{"agents", graphs.numRobots()},
                   {"graphs", graphs.numGraphs()},
                   {"states", graphs.totalStates()},
                   {"edges", edges},
                   {"map_cells", problem.map.numCells()},
                   {"load_s", load_s},
                   {"build_s", build_s},
                   {"graph_mb", graphs.memoryBytes() / 1048576.0},
                   {"peak_rss_mb", peakRssMb()}});
  });
}

}  // namespace fleet_planner::cli
