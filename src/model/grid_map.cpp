#include "fleet_planner/model/grid_map.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

GridMap::GridMap(int width, int height, std::vector<std::uint8_t> blocked, double resolution,
                 MapOrigin origin)
    : width_(width),
      height_(height),
      blocked_(std::move(blocked)),
      resolution_(resolution),
      origin_(origin) {
  if (width <= 0 || height <= 0) {
    throw InvalidInput("map size must be positive, got " + std::to_string(width) + " x " +
                       std::to_string(height));
  }
  if (static_cast<long long>(width) * height > (1LL << 28)) {
    throw InvalidInput("map of " + std::to_string(width) + " x " + std::to_string(height) +
                       " cells is larger than the supported 2^28 cells");
  }
  if (blocked_.size() != static_cast<std::size_t>(width) * height) {
    throw InvalidInput("map data has " + std::to_string(blocked_.size()) + " cells, expected " +
                       std::to_string(width * height));
  }
  if (!(resolution > 0.0) || !std::isfinite(resolution)) {
    throw InvalidInput("map resolution must be a positive number");
  }
  if (!std::isfinite(origin.x) || !std::isfinite(origin.y) || !std::isfinite(origin.yaw)) {
    throw InvalidInput("map origin must be finite");
  }
}

int GridMap::numFreeCells() const {
  return static_cast<int>(std::count(blocked_.begin(), blocked_.end(), 0));
}

}  // namespace fleet_planner
