#include "fleet_planner/io/instance_generator.h"

#include <cmath>
#include <vector>
#include <string>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/graph_search.h"
#include "fleet_planner/runtime/random.h"

namespace fleet_planner {

namespace {

// A multiple of 0.1 in [lo, hi], written so that it prints as a short decimal.
double tenths(Rng& rng, double lo, double hi) {
  const auto a = static_cast<std::int64_t>(std::llround(lo * 10));
  const auto b = static_cast<std::int64_t>(std::llround(hi * 10));
  return static_cast<double>(rng.uniformInt(a, b)) / 10.0;
}

// A simple polygon of 3 to 8 vertices: one per angular sector, at a random angle within its
// sector and a random radius, so that the vertices go round the origin in order and no gap
// between them reaches half a turn (the polygon is star-shaped about the origin). A quarter of
// them are then shifted by up to half a cell, which may leave the origin off-centre or outside.
// Coordinates are multiples of 0.1; a draw that rounding makes degenerate is drawn again.
Footprint randomPolygon(Rng& rng, const GeneratorOptions& o) {
  constexpr double kTwoPi = 6.283185307179586;
  for (int draw = 0; draw < 1000; ++draw) {
    const int n = static_cast<int>(rng.uniformInt(3, 8));
    const double sector = kTwoPi / n;
    const double phase = rng.uniform01() * sector;
    std::vector<Eigen::Vector2d> points;
    for (int k = 0; k < n; ++k) {
      const double angle = phase + sector * (k + 0.4 * (rng.uniform01() - 0.5));
      const double r = tenths(rng, o.min_size, o.max_size);
      points.emplace_back(std::round(r * std::cos(angle) * 10) / 10, std::round(r * std::sin(angle) * 10) / 10);
    }
    if (rng.uniformInt(0, 3) == 0) {
      const Eigen::Vector2d shift(tenths(rng, -0.5, 0.5), tenths(rng, -0.5, 0.5));
      for (auto& p : points) {
        p = {std::round((p.x() + shift.x()) * 10) / 10, std::round((p.y() + shift.y()) * 10) / 10};
      }
    }
    Footprint f = Footprint::polygon(std::move(points));
    if (footprintProblem(f).empty()) return f;
  }
  throw InvalidInput("generator: no usable polygon with vertices " + std::to_string(o.min_size) + " to " +
                     std::to_string(o.max_size) + " cells from the origin");
}

Footprint randomFootprint(Rng& rng, bool circle, const GeneratorOptions& o) {
  if (circle) return Footprint::circle(tenths(rng, o.min_radius, o.max_size));
  if (o.polygon_share > 0 && rng.uniform01() < o.polygon_share) return randomPolygon(rng, o);
  const double min_x = -tenths(rng, o.min_size, o.max_size);
  const double max_x = tenths(rng, o.min_size, o.max_size);
  const double half_width = tenths(rng, o.min_size, o.max_size);
  return Footprint::block(min_x, -half_width, max_x, half_width);
}

}  // namespace

bool placeRobot(const FleetGraphs& graphs, Instance& instance, int robot, const std::vector<bool>& others,
                Rng& rng, int attempts) {
  const StateGraph& g = graphs.graph(robot);
  const FootprintCells& cells = graphs.cells(robot);
  auto clashes = [&](const GridPose& pose, bool with_starts) {
    for (std::size_t j = 0; j < others.size(); ++j) {
      if (!others[j]) continue;
      const Robot& other = instance.robots[j];
      if (footprintsOverlap(cells, pose, graphs.cells(j), with_starts ? other.start : other.target)) return true;
    }
    return false;
  };
  for (int attempt = 0; attempt < attempts; ++attempt) {
    const StateId s = static_cast<StateId>(rng.uniformInt(0, g.stateIdCount() - 1));
    if (!g.valid(s) || clashes(g.pose(s), true)) continue;
    const std::vector<StateId> reachable = reachableFrom(g, s);
    for (int tries = 0; tries < 50; ++tries, ++attempt) {
      const StateId t = reachable[rng.uniformInt(0, static_cast<std::int64_t>(reachable.size()) - 1)];
      if (t == s || clashes(g.pose(t), false)) continue;
      instance.robots[robot].start = g.pose(s);
      instance.robots[robot].target = g.pose(t);
      return true;
    }
  }
  return false;
}

Instance generateInstance(const GridMap& map, const GeneratorOptions& options) {
  if (options.robots < 0) throw InvalidInput("generator: number of robots must not be negative");
  if (!(options.polygon_share >= 0 && options.polygon_share <= 1)) {
    throw InvalidInput("generator: polygon_share must be in [0, 1]");
  }
  Rng rng(options.seed);
  Instance instance;
  std::vector<Footprint> footprints;
  for (int i = 0; i < options.robots; ++i) footprints.push_back(randomFootprint(rng, i % 2 == 0, options));
  const FleetGraphs graphs(map, footprints, options.model);
  std::vector<bool> placed(options.robots, false);  // the robots placed so far
  for (int i = 0; i < options.robots; ++i) {
    Robot robot;
    robot.id = std::to_string(i);
    robot.footprint = footprints[i];
    instance.robots.push_back(std::move(robot));
    if (!placeRobot(graphs, instance, i, placed, rng, options.attempts_per_robot)) {
      throw InvalidInput("generator: could not place robot " + std::to_string(i) + " (" +
                         footprints[i].describe() + ") on " +
                         (map.source().empty() ? std::string("the map") : map.source()) + " after " +
                         std::to_string(options.attempts_per_robot) + " attempts");
    }
    placed[i] = true;
  }
  return instance;
}

}  // namespace fleet_planner
