#pragma once
/// A footprint discretised on the grid (paper: Preliminaries, "Collision detection"): the cells
/// it covers at each heading, [a_i, s], and the cells it sweeps during each action,
/// [a_i, s, s'], all relative to the cell the robot stands on.
///
/// - A cell is covered when the footprint overlaps the cell's square with positive area.
/// - A move of k cells sweeps the union of the footprints at every cell on the way (k + 1 of
///   them): exact for a straight translation along a grid axis. Moves of every length up to the
///   lattice step are kept (the lattice's own moves, and the shorter ones that connect a pose
///   to it).
/// - A rotation sweeps both footprints and every cell the footprint passes over while it turns
///   90 degrees about its origin. This is exact for footprints that are star-shaped about the
///   origin (circles, blocks and convex polygons containing the origin, most real robots); for
///   other polygons it is the sweep of their star hull (the union of triangles from the origin
///   to each edge), a superset, so collision checks stay safe.
#include <array>
#include <cmath>
#include <functional>
#include <memory>

#include "fleet_planner/model/action.h"
#include "fleet_planner/model/cell_set.h"
#include "fleet_planner/model/footprint.h"

namespace fleet_planner {

class FootprintCells {
 public:
  /// Moves advance `step` cells (ActionModel::step, >= 1). Throws InvalidInput if the footprint
  /// is not usable (see footprintProblem()).
  explicit FootprintCells(const Footprint& footprint, int step = 1);

  const Footprint& footprint() const { return footprint_; }
  /// Cells covered at `heading`, relative to the robot's cell.
  const CellSet& body(int heading) const { return body_[heading]; }
  /// Cells covered while doing `action` from `heading`, relative to the starting cell (a move:
  /// of `step()` cells).
  const CellSet& swept(int heading, Action action) const {
    return swept_[heading][static_cast<int>(action)];
  }
  /// Cells covered by a move of `length` cells (1..step()) from `heading`, forward or backward.
  const CellSet& moveSwept(int heading, bool forward, int length) const {
    return moves_[heading][forward ? 0 : 1][length - 1];
  }
  int step() const { return step_; }
  /// Largest squared length of any offset in any body or sweep.
  int maxNormSq() const { return max_norm_sq_; }
  /// A radius, in cells, that no cell of any body or sweep reaches from the robot's cell: two
  /// robots farther apart than the sum of their reaches cannot meet.
  int reach() const { return static_cast<int>(std::ceil(std::sqrt(static_cast<double>(max_norm_sq_)))) + 1; }

  /// Same cells in every body and sweep: robots with such footprints share one state graph.
  bool sameCells(const FootprintCells& other) const;
  /// Hash of the cells, consistent with sameCells().
  std::size_t cellsHash() const { return hash_; }

 private:
  Footprint footprint_;
  std::array<CellSet, kHeadings> body_;
  std::array<std::array<CellSet, kActions>, kHeadings> swept_;
  int step_ = 1;
  std::array<std::array<std::vector<CellSet>, 2>, kHeadings> moves_;  ///< [heading][forward?0:1][length-1]
  int max_norm_sq_ = 0;
  std::size_t hash_ = 0;
};

/// FootprintCells(footprint, step), built once per process and shared: the planner, the
/// validator, the earliest schedule and the execution checks each need the cells of every robot,
/// and a fleet has few distinct footprints. Thread-safe; the last 64 distinct (footprint, step)
/// pairs built are kept. Throws InvalidInput as the constructor does.
std::shared_ptr<const FootprintCells> sharedFootprintCells(const Footprint& footprint, int step = 1);

/// Cells the footprint covers at any `yaw` (radians), relative to its cell: for starts and
/// targets off the grid headings.
CellSet footprintCellsAt(const Footprint& footprint, double yaw);
/// Same with the footprint's origin `offset` cells from the centre of the cell it stands on (a
/// robot between cells, as a pose from TF puts it; |offset| up to half a cell on each axis).
CellSet footprintCellsAt(const Footprint& footprint, double yaw, const Eigen::Vector2d& offset);

/// Cells the footprint covers turning in place from `from_yaw` to `to_yaw` the shorter way (at
/// most half a turn), both end poses included; exact for star-shaped footprints as the grid
/// rotations are, within the footprint's sweep_tolerance.
CellSet turnSweep(const Footprint& footprint, double from_yaw, double to_yaw);

}  // namespace fleet_planner
