#pragma once
/// Fast "does this cell set, placed here, touch an obstacle?" for one map.
///
/// Two tables, both flat over the cells: the exact squared Euclidean distance from each cell to
/// the nearest blocked cell (cells outside the map count as blocked), so that a set whose
/// farthest offset is nearer than that needs no check at all; and per-row prefix counts of
/// blocked cells, so that the exact check costs one subtraction per run of the set.
#include <cstdint>
#include <vector>

#include "fleet_planner/model/cell_set.h"
#include "fleet_planner/model/grid_map.h"

namespace fleet_planner {

class ObstacleIndex {
 public:
  /// How the clearance table is made. Euclidean: exact (a distance transform, about 300
  /// instructions a cell), for a map's walls, where the graphs ask millions of placements.
  /// Chessboard: the chessboard distance, a lower bound (two integer passes, ten times
  /// cheaper), for the few footprints of other robots that a subproblem or a legality check
  /// blocks: most placements are far from all of them either way.
  enum class Clearance { Euclidean, Chessboard };
  explicit ObstacleIndex(const GridMap& map, Clearance clearance = Clearance::Euclidean);

  /// Squared distance (in cells) from cell (x, y), inside the map, to the nearest blocked cell.
  std::int64_t clearanceSq(int x, int y) const { return clearance_sq_[y * width_ + x]; }

  /// True when `set` placed at `origin` covers a blocked cell or leaves the map.
  bool blocked(const CellSet& set, Cell origin) const;

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<std::int64_t> clearance_sq_;
  std::vector<std::int32_t> row_prefix_;  // (width + 1) per row: blocked cells left of x
};

/// Exact squared Euclidean distance transform (Felzenszwalb & Huttenlocher 2012) of a grid
/// padded by one blocked cell on every side: for each cell, the squared distance to the
/// nearest blocked cell or to the outside of the map.
std::vector<std::int64_t> squaredDistanceToBlocked(const GridMap& map);

/// The same padded grid's squared chessboard distance (max(|dx|, |dy|) squared, a lower bound
/// on the squared Euclidean distance) from each cell to the nearest blocked cell or the outside.
std::vector<std::int64_t> squaredChessboardToBlocked(const GridMap& map);

}  // namespace fleet_planner
