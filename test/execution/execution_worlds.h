#pragma once
// Plans for the execution tests: random small worlds planned with planFleet (mixed footprints,
// starts and targets at any yaw, lattices of one cell and coarser), each checked by the
// validator; and the dependency rule written the slow, obvious way, as a reference.
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "fleet_planner/execution/plan_cells.h"
#include "fleet_planner/execution/step_dependencies.h"
#include "fleet_planner/io/instance_generator.h"
#include "fleet_planner/model/collision.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/planning/plan_fleet.h"
#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/runtime/random.h"
#include "layered/random_worlds.h"
#include "test_maps.h"
#include "test_robots.h"

namespace fleet_planner::test {

constexpr double kPi = 3.141592653589793;

/// A planned world: map, instance, plan and the model it was planned under.
struct PlannedWorld {
  GridMap map = freeMap(1, 1);
  Instance instance;
  Plan plan;
  ActionModel model;
  std::string name;
};

inline PlanningOptions executionPlanning(std::uint64_t seed, int lattice_step) {
  PlanningOptions o;
  o.threads = 1;
  o.time_limit = 0.5;  // a world the planner finds hard is skipped: the next seed
  o.seed = seed;
  o.lattice_step = lattice_step;
  return o;
}

/// Plans `instance` on `map`; the plan only when planFleet succeeds and the validator accepts it.
inline std::optional<PlannedWorld> planWorld(const GridMap& map, const Instance& instance,
                                             const PlanningOptions& options, const std::string& name) {
  const PlanningResult r = planFleet(map, instance, options);
  if (!r.success()) return std::nullopt;
  PlannedWorld w;
  w.map = map;
  w.instance = instance;
  w.plan = r.plan;
  w.model = options.model;
  w.model.step = r.lattice_step;
  w.name = name + " (lattice " + std::to_string(r.lattice_step) + ")";
  if (!validatePlan(w.map, w.instance, w.plan, w.model).valid())
    throw std::logic_error(name + ": planFleet returned an invalid plan");
  return w;
}

/// A small random map with mixed robots (circles, blocks, polygons; up to a cell or so), about
/// a third of them starting and a third ending at a random yaw, planned on the one-cell lattice.
inline std::optional<PlannedWorld> randomCellWorld(std::uint64_t seed, int robots) {
  const GridMap map = randomMap(seed, 12, 12, 4, 14);
  GeneratorOptions g;
  g.robots = robots;
  g.seed = seed;
  g.max_size = 1.0;
  g.polygon_share = 0.5;
  Instance instance;
  try {
    instance = generateInstance(map, g);
  } catch (const InvalidInput&) {
    return std::nullopt;
  }
  Rng rng(seed * 7919 + 1);
  for (Robot& r : instance.robots) {
    if (rng.uniformInt(0, 3) == 0) r.start_yaw = -kPi + 2 * kPi * rng.uniform01();
    if (rng.uniformInt(0, 3) == 0) r.target_yaw = -kPi + 2 * kPi * rng.uniform01();
  }
  return planWorld(map, instance, executionPlanning(seed, 1), "cell world " + std::to_string(seed));
}

/// A 36 x 26 map with a few pillars and `robots` blocks of 3-5 cells, planned on a lattice of
/// `step` cells (their starts and targets off it: connecting moves shorter than the step).
inline std::optional<PlannedWorld> randomLatticeWorld(std::uint64_t seed, int robots, int step) {
  Rng rng(seed);
  std::vector<std::string> rows(26, std::string(36, '.'));
  for (int k = 0; k < 4; ++k) {
    const int x = static_cast<int>(rng.uniformInt(6, 27)), y = static_cast<int>(rng.uniformInt(5, 18));
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) rows[y + dy][x + dx] = '@';
  }
  const GridMap map = mapFromRows(rows);
  Instance instance;
  auto fits = [&](const FootprintCells& cells, const GridPose& p, bool start) {
    for (const Cell& c : cells.body(p.heading).cells())
      if (map.blocked(p.x + c.x, p.y + c.y)) return false;
    for (const Robot& o : instance.robots) {
      const GridPose& q = start ? o.start : o.target;
      if (footprintsOverlap(cells, p, FootprintCells(o.footprint), q)) return false;
    }
    return true;
  };
  for (int attempt = 0; static_cast<int>(instance.robots.size()) < robots && attempt < 2000; ++attempt) {
    const double l = static_cast<double>(rng.uniformInt(3, 5)), w = static_cast<double>(rng.uniformInt(3, 4));
    auto pose = [&] {
      return GridPose{static_cast<int>(rng.uniformInt(3, 32)), static_cast<int>(rng.uniformInt(3, 22)),
                      static_cast<int>(rng.uniformInt(0, 3))};
    };
    Robot r = makeRobot(std::to_string(instance.robots.size()), Footprint::block(-l / 2, -w / 2, l / 2, w / 2),
                        pose(), pose());
    const FootprintCells cells(r.footprint);
    if (fits(cells, r.start, true) && fits(cells, r.target, false)) instance.robots.push_back(r);
  }
  if (rng.uniformInt(0, 1) == 0) instance.robots.front().start_yaw = 0.7;
  if (rng.uniformInt(0, 1) == 0) instance.robots.back().target_yaw = -2.2;
  return planWorld(map, instance, executionPlanning(seed, step), "lattice world " + std::to_string(seed));
}

/// The random worlds of the execution tests, planned once per test binary: the first 12 cell
/// worlds (7 robots) and the first 5 lattice worlds (5 robots, lattices of 2 and 3) the planner
/// solves, of the seeds from 1 on.
inline const std::vector<PlannedWorld>& testWorlds() {
  static const std::vector<PlannedWorld> all = [] {
    std::vector<PlannedWorld> w;
    for (std::uint64_t seed = 1, found = 0; seed <= 40 && found < 12; ++seed) {
      if (auto world = randomCellWorld(seed, 7)) w.push_back(std::move(*world)), ++found;
    }
    for (std::uint64_t seed = 1, found = 0; seed <= 20 && found < 5; ++seed) {
      if (auto world = randomLatticeWorld(seed, 5, seed % 2 ? 3 : 2)) w.push_back(std::move(*world)), ++found;
    }
    return w;
  }();
  return all;
}

/// The dependency rule of step_dependencies.h written directly: for each move t of robot i and
/// each other robot j, the last T < t at which j's cells during step T share a cell with i's
/// during t; j must reach T + 1; requirements already made by an earlier move of i are dropped.
inline StepDependencies referenceDependencies(const PlanCells& cells) {
  const int n = cells.robots();
  StepDependencies deps;
  deps.before.resize(n);
  for (int i = 0; i < n; ++i) {
    deps.before[i].resize(cells.lastState(i));
    std::vector<int> required(n, 0);
    for (int t = 0; t < cells.lastState(i); ++t) {
      if (!cells.isMove(i, t)) continue;
      for (int j = 0; j < n; ++j) {
        if (j == i) continue;
        for (int last = t - 1; last >= 0; --last) {
          if (!overlap(cells.during(i, t), cells.during(j, last))) continue;
          if (last + 1 > required[j]) {
            required[j] = last + 1;
            deps.before[i][t].push_back({j, last + 1});
          }
          break;
        }
      }
    }
  }
  return deps;
}

/// The state graphs of a planned world's robots.
inline FleetGraphs graphsOf(const PlannedWorld& w) {
  std::vector<Footprint> footprints;
  for (const Robot& r : w.instance.robots) footprints.push_back(r.footprint);
  return FleetGraphs(w.map, footprints, w.model);
}

}  // namespace fleet_planner::test
