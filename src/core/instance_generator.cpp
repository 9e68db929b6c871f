#include "fleet_planner/core/instance_generator.h"

#include <cmath>
#include <string>

#include "fleet_planner/core/collision.h"
#include "fleet_planner/core/errors.h"
#include "fleet_planner/core/fleet_graphs.h"
#include "fleet_planner/core/graph_search.h"
#include "fleet_planner/core/random.h"

namespace fleet_planner {

namespace {

// A multiple of 0.1 in [lo, hi], written so that it prints as a short decimal.
double tenths(Rng& rng, double lo, double hi) {
  const auto a = static_cast<std::int64_t>(std::llround(lo * 10));
  const auto b = static_cast<std::int64_t>(std::llround(hi * 10));
  return static_cast<double>(rng.uniformInt(a, b)) / 10.0;
}

Footprint randomFootprint(Rng& rng, bool circle, const GeneratorOptions& o) {
  if (circle) return Footprint::circle(tenths(rng, o.min_radius, o.max_size));
  const double min_x = -tenths(rng, o.min_size, o.max_size);
  const double max_x = tenths(rng, o.min_size, o.max_size);
  const double half_width = tenths(rng, o.min_size, o.max_size);
  return Footprint::block(min_x, -half_width, max_x, half_width);
}

}  // namespace

Instance generateInstance(const GridMap& map, const GeneratorOptions& options) {
  if (options.robots < 0) throw InvalidInput("generator: number of robots must not be negative");
  Rng rng(options.seed);
  Instance instance;
  std::vector<Footprint> footprints;
  for (int i = 0; i < options.robots; ++i) footprints.push_back(randomFootprint(rng, i % 2 == 0, options));
  const FleetGraphs graphs(map, footprints, options.model);

  for (int i = 0; i < options.robots; ++i) {
    const StateGraph& g = graphs.graph(i);
    const FootprintCells& cells = graphs.cells(i);
    auto clashes = [&](const GridPose& pose, bool with_starts) {
      for (int j = 0; j < i; ++j) {
        const Robot& other = instance.robots[j];
        if (footprintsOverlap(cells, pose, graphs.cells(j), with_starts ? other.start : other.target)) return true;
      }
      return false;
    };
    Robot robot;
    robot.id = std::to_string(i);
    robot.footprint = footprints[i];
    bool placed = false;
    for (int attempt = 0; attempt < options.attempts_per_robot && !placed; ++attempt) {
      const StateId s = static_cast<StateId>(rng.uniformInt(0, g.stateIdCount() - 1));
      if (!g.valid(s) || clashes(g.pose(s), true)) continue;
      const std::vector<StateId> reachable = reachableFrom(g, s);
      for (int tries = 0; tries < 50 && !placed; ++tries, ++attempt) {
        const StateId t = reachable[rng.uniformInt(0, static_cast<std::int64_t>(reachable.size()) - 1)];
        if (t == s || clashes(g.pose(t), false)) continue;
        robot.start = g.pose(s);
        robot.target = g.pose(t);
        placed = true;
      }
    }
    if (!placed) {
      throw InvalidInput("generator: could not place robot " + std::to_string(i) + " (" +
                         footprints[i].describe() + ") on " +
                         (map.source().empty() ? std::string("the map") : map.source()) + " after " +
                         std::to_string(options.attempts_per_robot) + " attempts");
    }
    instance.robots.push_back(std::move(robot));
  }
  return instance;
}

}  // namespace fleet_planner
