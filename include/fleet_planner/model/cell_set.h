#pragma once
/// A finite set of cells relative to an origin cell, stored as horizontal runs sorted by row.
/// Footprints and swept areas are CellSets; placing one at a cell and testing it against another
/// placed elsewhere is a merge over the runs, with a bounding-box reject first.
#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "fleet_planner/model/types.h"

namespace fleet_planner {

class CellSet {
 public:
  struct Run {
    int dy = 0;
    int x0 = 0;  ///< first column, inclusive
    int x1 = 0;  ///< last column, inclusive
    friend bool operator==(const Run& a, const Run& b) {
      return a.dy == b.dy && a.x0 == b.x0 && a.x1 == b.x1;
    }
  };

  CellSet() = default;
  /// Builds the set of the given offsets (duplicates allowed).
  static CellSet fromCells(std::vector<Cell> cells);

  const std::vector<Run>& runs() const { return runs_; }
  bool empty() const { return runs_.empty(); }
  /// Number of cells.
  std::size_t size() const { return size_; }
  bool contains(int dx, int dy) const;
  /// The member offsets, sorted by row then column.
  std::vector<Cell> cells() const;

  /// Bounding box of the offsets (meaningless when empty).
  int minX() const { return min_x_; }
  int maxX() const { return max_x_; }
  int minY() const { return min_y_; }
  int maxY() const { return max_y_; }
  /// Largest squared Euclidean length of a member offset.
  int maxNormSq() const { return max_norm_sq_; }

  /// This set together with `other` shifted by `shift`.
  CellSet unionWith(const CellSet& other, Cell shift) const;

  /// True when `a` placed at cell `pa` and `b` placed at cell `pb` share a cell.
  static bool overlap(const CellSet& a, Cell pa, const CellSet& b, Cell pb) {
    Cell unused;
    return commonCell(a, pa, b, pb, unused);
  }
  /// Like overlap(); on true, `cell` is the first shared cell (map coordinates, row-major order).
  static bool commonCell(const CellSet& a, Cell pa, const CellSet& b, Cell pb, Cell& cell);

  friend bool operator==(const CellSet& a, const CellSet& b) { return a.runs_ == b.runs_; }
  friend bool operator!=(const CellSet& a, const CellSet& b) { return !(a == b); }

 private:
  std::vector<Run> runs_;
  std::size_t size_ = 0;
  int min_x_ = 0, max_x_ = 0, min_y_ = 0, max_y_ = 0;
  int max_norm_sq_ = 0;
};

/// Calls f(index) for each cell of `set` placed at `origin` that lies on a map of width x height
/// cells (index = y * width + x), row by row. When f returns bool, false stops the walk and the
/// result is false; otherwise the result is true.
template <class F>
bool forEachMapCell(const CellSet& set, Cell origin, int width, int height, F&& f) {
  for (const CellSet::Run& r : set.runs()) {
    const int y = origin.y + r.dy;
    if (y < 0 || y >= height) continue;
    const std::size_t row = static_cast<std::size_t>(y) * width;
    const int x0 = std::max(origin.x + r.x0, 0), x1 = std::min(origin.x + r.x1, width - 1);
    for (int x = x0; x <= x1; ++x) {
      if constexpr (std::is_same_v<std::invoke_result_t<F&, std::size_t>, bool>) {
        if (!f(row + x)) return false;
      } else {
        f(row + x);
      }
    }
  }
  return true;
}

}  // namespace fleet_planner
