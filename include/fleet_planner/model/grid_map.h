#pragma once
/// The workspace (paper: Preliminaries, "Workspace"): a grid of passable and blocked cells, with
/// the metric frame it sits in. Cells outside the grid count as blocked.
#include <cstdint>
#include <string>
#include <vector>

#include "fleet_planner/model/types.h"

namespace fleet_planner {

/// Where the grid sits in the world: cell (0, 0) has its lower corner at (x, y); yaw in radians.
struct MapOrigin {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
};

class GridMap {
 public:
  GridMap() = default;
  /// `blocked` has width * height entries, row-major (index = y * width + x), nonzero = blocked.
  /// Throws InvalidInput for non-positive sizes, a size mismatch or a non-positive resolution.
  GridMap(int width, int height, std::vector<std::uint8_t> blocked, double resolution = 1.0,
          MapOrigin origin = {});

  int width() const { return width_; }
  int height() const { return height_; }
  int numCells() const { return width_ * height_; }
  /// Metres per cell.
  double resolution() const { return resolution_; }
  const MapOrigin& origin() const { return origin_; }

  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  /// True for blocked cells and for every cell outside the grid.
  bool blocked(int x, int y) const { return !inside(x, y) || blocked_[index(x, y)] != 0; }
  int index(int x, int y) const { return y * width_ + x; }
  Cell cellOf(int index) const { return {index % width_, index / width_}; }
  int numFreeCells() const;

  /// Row-major occupancy, nonzero = blocked.
  const std::vector<std::uint8_t>& cells() const { return blocked_; }

  /// Where the map came from (a file name), for messages.
  const std::string& source() const { return source_; }
  void setSource(std::string source) { source_ = std::move(source); }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> blocked_;
  double resolution_ = 1.0;
  MapOrigin origin_;
  std::string source_;
};

}  // namespace fleet_planner
