#include "bench_problems.h"

#include <cstdlib>
#include <map>
#include <exception>
#include <utility>

#include "fleet_planner/io/instance_generator.h"
#include "fleet_planner/io/instance_io.h"
#include "fleet_planner/io/map_io.h"

namespace fleet_planner::bench {

const FleetGraphs& Problem::fleetGraphs() {
  if (!graphs) {
    std::vector<Footprint> footprints;
    for (const auto& r : instance.robots) footprints.push_back(r.footprint);
    graphs = std::make_unique<FleetGraphs>(map, footprints, ActionModel{}, 1);
  }
  return *graphs;
}

std::string benchmarkDir() {
  const char* env = std::getenv("FLEET_PLANNER_BENCHMARK");
  return env != nullptr && *env != '\0' ? env : FLEET_PLANNER_BENCHMARK_DIR;
}

Problem* problem(const std::string& name, int k, std::string& error) {
  static std::map<std::pair<std::string, int>, std::unique_ptr<Problem>> cache;
  auto& slot = cache[{name, k}];
  if (slot) return slot.get();
  const std::string dir = benchmarkDir();
  try {
    auto p = std::make_unique<Problem>();
    p->map = loadMap(dir + "/maps/" + name + ".map");
    p->instance = selectMixed(loadInstance(dir + "/instances/" + name + "_la.txt"), k);
    slot = std::move(p);
    return slot.get();
  } catch (const std::exception& e) {
    error = std::string(e.what()) + " (benchmark folder " + dir + "; set FLEET_PLANNER_BENCHMARK)";
    return nullptr;
  }
}

Problem* generatedProblem(const std::string& name, int robots, unsigned seed, std::string& error) {
  static std::map<std::pair<std::string, std::pair<int, unsigned>>, std::unique_ptr<Problem>> cache;
  auto& slot = cache[{name, {robots, seed}}];
  if (slot) return slot.get();
  const std::string dir = benchmarkDir();
  try {
    auto p = std::make_unique<Problem>();
    p->map = loadMap(dir + "/maps/" + name + ".map");
    GeneratorOptions options;
    options.robots = robots;
    options.seed = seed;
    p->instance = generateInstance(p->map, options);
    slot = std::move(p);
    return slot.get();
  } catch (const std::exception& e) {
    error = std::string(e.what()) + " (benchmark folder " + dir + "; set FLEET_PLANNER_BENCHMARK)";
    return nullptr;
  }
}

Subproblem wholeFleet(Problem& p, long long budget) {
  Subproblem sub;
  sub.instance = &p.instance;
  sub.graphs = &p.fleetGraphs();
  for (std::size_t i = 0; i < p.instance.robots.size(); ++i) sub.robots.push_back(static_cast<int>(i));
  sub.deadline = Deadline::in(600.0);
  sub.seed = 1;
  sub.max_expansions = budget;
  return sub;
}

}  // namespace fleet_planner::bench
