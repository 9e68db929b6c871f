#pragma once
// Random tiny worlds for the tests that compare a search with the exhaustive reference
// (exhaustive_search.h): a few cells, a few walls, 2-3 dots and bars at random poses.
#include <memory>
#include <string>
#include <vector>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/runtime/random.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {

// A random map of at most 20 cells (12 for three robots) with a few walls and 2-3 dots and bars at random poses; the
// World constructor rejects overlapping or illegal poses, and such draws are drawn again.
inline std::unique_ptr<World> randomTinyWorld(Rng& rng, int robots) {
  const int cells = robots == 2 ? 20 : 12;
  for (;;) {
    const int width = static_cast<int>(rng.uniformInt(3, 5));
    const int height = static_cast<int>(rng.uniformInt(2, cells / width));
    std::vector<std::string> rows(height, std::string(width, '.'));
    for (int k = static_cast<int>(rng.uniformInt(0, 3)); k > 0; --k)
      rows[rng.uniformInt(0, height - 1)][rng.uniformInt(0, width - 1)] = '@';
    auto pose = [&] {
      return GridPose{static_cast<int>(rng.uniformInt(0, width - 1)), static_cast<int>(rng.uniformInt(0, height - 1)),
                      static_cast<int>(rng.uniformInt(0, 3))};
    };
    std::vector<Robot> fleet;
    for (int i = 0; i < robots; ++i) {
      const std::string id = "r" + std::to_string(i);
      fleet.push_back(rng.uniformInt(0, 3) == 0 ? bar(id, pose(), pose()) : dot(id, pose(), pose()));
    }
    try {
      return std::make_unique<World>(mapFromRows(rows), fleet);
    } catch (const InvalidInput&) {
    }
  }
}

}  // namespace fleet_planner::test
