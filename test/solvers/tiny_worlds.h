#pragma once
// Tiny worlds for the tests that compare a search with the exhaustive reference
// (exhaustive_search.h): random ones (a few cells, a few walls, 2-3 dots and bars at random
// poses), and a corridor that holds a robot's target; and two swaps that cannot be done.
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

// Two rooms joined by a one-cell corridor. a's target lies in the corridor, b must pass through
// it from the other room, c crosses the lower room. The optimum is 46 (by exhaustive search).
inline World corridorToATarget() {
  return World(mapFromRows({"@@@@@@@@@@", "@........@", "@........@", "@@@@.@@@@@", "@@@@.@@@@@", "@@@@.@@@@@",
                            "@@@@.@@@@@", "@........@", "@........@", "@@@@@@@@@@"}),
               {dot("a", {2, 8, 0}, {4, 4, 3}), dot("b", {4, 1, 2}, {6, 8, 0}), dot("c", {7, 7, 1}, {1, 1, 0})});
}

// Two dots swapping ends of a one-row corridor n cells long: impossible.
inline World swapInARow(int n) {
  return World(freeMap(n, 1), {dot("a", {0, 0, 0}, {n - 3, 0, 0}), dot("b", {n - 3, 0, 2}, {0, 0, 2})});
}

// The same swap in the top row of two, the lower row a wall but for a pocket at its end, where
// a third dot stands at its target: still impossible, with the pocket free or not.
inline World swapInACorridorWithAPocket(int n) {
  return World(mapFromRows({std::string(n, '.'), std::string(n - 1, '@') + "."}),
               {dot("a", {0, 0, 0}, {n - 3, 0, 0}), dot("b", {n - 3, 0, 2}, {0, 0, 2}),
                dot("c", {n - 1, 1, 1}, {n - 1, 1, 1})});
}

}  // namespace fleet_planner::test
