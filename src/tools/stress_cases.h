#pragma once
/// Random small LA-MAPF instances for `fleet_planner_cli stress`: a map (random obstacles,
/// rooms, corridors or a crop of a benchmark map) and 2..8 robots of mixed footprints (circles,
/// blocks, polygons) from the core generator. Instance `index` of base seed `seed` is always the
/// same, whatever other instances a sweep runs, so one failing instance can be re-run alone.
#include <cstdint>
#include <string>
#include <vector>

#include "fleet_planner/model/action.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/instance.h"

namespace fleet_planner::cli {

struct StressCaseOptions {
  std::uint64_t seed = 0;
  int min_robots = 2;
  int max_robots = 8;
  int min_side = 8;
  int max_side = 32;
  /// Maps to crop from (a quarter of the instances, when not empty); their source() names them.
  std::vector<GridMap> crop_maps;
};

struct StressCase {
  int index = 0;
  std::uint64_t seed = 0;  ///< the instance's own seed (derived from the base seed and index)
  std::string map_kind;    ///< "random", "rooms", "corridors", "crop:<file>"
  GridMap map;
  Instance instance;
  ActionModel model;
  int generator_retries = 0;  ///< placements that failed before this one succeeded
};

/// The seed of instance `index` of a sweep with base seed `seed`.
std::uint64_t stressCaseSeed(std::uint64_t seed, int index);

/// Instance `index`. Throws InvalidInput only if no instance could be placed at all after many
/// tries (a bug or an unusable crop map).
StressCase makeStressCase(const StressCaseOptions& options, int index);

/// The map as MovingAI text ('.' free, '@' blocked), for dumping a failing instance.
std::string movingAiText(const GridMap& map);

}  // namespace fleet_planner::cli
