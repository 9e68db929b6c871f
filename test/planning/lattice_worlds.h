#pragma once
// Fleets for the lattice tests: block robots, options for one lattice step, and random worlds of
// robots 4-7 cells long on a map with pillars.
#include <string>
#include <vector>

#include "fleet_planner/model/footprint_cells.h"
#include "fleet_planner/planning/plan_fleet.h"
#include "fleet_planner/runtime/random.h"
#include "test_maps.h"
#include "test_robots.h"

namespace fleet_planner::test {

/// A robot `w` cells wide and `l` long (a block about its centre cell).
inline Robot box(const std::string& id, double l, double w, GridPose start, GridPose target) {
  return makeRobot(id, Footprint::block(-l / 2, -w / 2, l / 2, w / 2), start, target);
}

inline PlanningOptions onLattice(int step) {
  PlanningOptions o;
  o.lattice_step = step;
  o.threads = 1;
  o.time_limit = 20.0;
  return o;
}

/// A 72 x 48 map with a few pillars, and `n` robots of 4-7 cells at random free, non-overlapping
/// grid poses (seeded).
struct RandomWorld {
  GridMap map = freeMap(72, 48);
  Instance instance;
  RandomWorld(int n, std::uint64_t seed) {
    std::vector<std::string> rows(48, std::string(72, '.'));
    Rng rng(seed);
    for (int k = 0; k < 6; ++k) {
      const int x = static_cast<int>(rng.uniformInt(10, 60)), y = static_cast<int>(rng.uniformInt(8, 38));
      for (int dy = 0; dy < 3; ++dy)
        for (int dx = 0; dx < 3; ++dx) rows[y + dy][x + dx] = '@';
    }
    map = mapFromRows(rows);
    std::vector<Robot> robots;
    auto fits = [&](const Robot& r, bool start) {
      const FootprintCells cells(r.footprint);
      const GridPose& p = start ? r.start : r.target;
      for (const Cell& c : cells.body(p.heading).cells()) {
        if (map.blocked(p.x + c.x, p.y + c.y)) return false;
      }
      for (const Robot& o : robots) {
        if (footprintsOverlapRough(r, p, o, start ? o.start : o.target)) return false;
      }
      return true;
    };
    for (int i = 0; robots.size() < static_cast<std::size_t>(n) && i < 10000; ++i) {
      const double l = static_cast<double>(rng.uniformInt(4, 7)), w = static_cast<double>(rng.uniformInt(4, 6));
      auto pose = [&] {
        return GridPose{static_cast<int>(rng.uniformInt(5, 66)), static_cast<int>(rng.uniformInt(5, 42)),
                        static_cast<int>(rng.uniformInt(0, 3))};
      };
      Robot r = box(std::to_string(robots.size()), l, w, pose(), pose());
      if (fits(r, true) && fits(r, false)) robots.push_back(r);
    }
    instance.robots = robots;
  }
  // Circumscribed discs apart (conservative and cheap).
  static bool footprintsOverlapRough(const Robot& a, const GridPose& pa, const Robot& b, const GridPose& pb) {
    const double reach = a.footprint.circumscribedRadius() + b.footprint.circumscribedRadius() + 1.5;
    const double dx = pa.x - pb.x, dy = pa.y - pb.y;
    return dx * dx + dy * dy < reach * reach;
  }
};

}  // namespace fleet_planner::test
