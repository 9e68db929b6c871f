#pragma once
// Seeded random worlds for the layered tests: small maps with scattered obstacles, and fleets of
// generated robots no larger than a cell or so.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/io/instance_generator.h"
#include "fleet_planner/runtime/random.h"
#include "test_maps.h"

namespace fleet_planner::test {

/// A map of (min_width + 0..spread) x (min_height + 0..spread) cells with width * height /
/// cells_per_obstacle obstacles dropped at random, all drawn from `seed`.
inline GridMap randomMap(std::uint64_t seed, int min_width, int min_height, int spread, int cells_per_obstacle) {
  Rng rng(seed);
  const int w = min_width + static_cast<int>(rng.uniformInt(0, spread));
  const int h = min_height + static_cast<int>(rng.uniformInt(0, spread));
  std::vector<std::string> rows(h, std::string(w, '.'));
  for (int k = 0; k < w * h / cells_per_obstacle; ++k) rows[rng.uniformInt(0, h - 1)][rng.uniformInt(0, w - 1)] = '@';
  return mapFromRows(rows);
}

/// `robots` generated robots (footprints up to a cell) on `map`, or nothing when the generator
/// finds no room for them.
inline std::optional<Instance> randomFleet(const GridMap& map, int robots, std::uint64_t seed) {
  GeneratorOptions g;
  g.robots = robots;
  g.seed = seed;
  g.max_size = 1.0;
  try {
    return generateInstance(map, g);
  } catch (const InvalidInput&) {
    return std::nullopt;
  }
}

}  // namespace fleet_planner::test
