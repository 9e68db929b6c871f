#pragma once
/// A robot's shape in its own frame (+x forward), lengths in cells. Three kinds:
/// - circle of `radius` around the origin;
/// - block: the rectangle [min_x, max_x] x [min_y, max_y] (the benchmark's Block_2D);
/// - polygon: vertices in order (the costmap_2d `footprint` convention), convex or not.
/// The robot rotates about its origin, which sits at the centre of the cell the robot is on.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace fleet_planner {

struct Footprint {
  enum class Kind { Circle, Block, Polygon };

  Kind kind = Kind::Circle;
  double radius = 0.0;                  ///< circle
  double min_x = 0.0, max_x = 0.0;      ///< block
  double min_y = 0.0, max_y = 0.0;      ///< block
  std::vector<Eigen::Vector2d> points;  ///< polygon, in order
  /// How deep (cells) a rotation may clip a cell beyond its two end poses before that cell
  /// counts as swept, in [0, kMaxSweepTolerance]. 0 (the default) is the exact sweep. The
  /// benchmark pools were generated under a discretisation that leaves some such clips out (a
  /// block's corner may pass 0.1-0.35 cells into an obstacle cell while it turns), see
  /// docs/benchmarking.md; the poses themselves are always exact.
  double sweep_tolerance = 0.0;
  static constexpr double kMaxSweepTolerance = 0.25;

  static Footprint circle(double radius);
  static Footprint block(double min_x, double min_y, double max_x, double max_y);
  static Footprint polygon(std::vector<Eigen::Vector2d> points);

  /// The outline as a polygon (a block's four corners; empty for a circle).
  std::vector<Eigen::Vector2d> outline() const;
  /// Largest distance from the origin to any point of the footprint.
  double circumscribedRadius() const;
  /// "circle r=1.5", "block [-1,2]x[-0.5,0.5]", "polygon of 5 points".
  std::string describe() const;

  friend bool operator==(const Footprint& a, const Footprint& b);
  friend bool operator!=(const Footprint& a, const Footprint& b) { return !(a == b); }
};

/// Empty when the footprint is usable, otherwise the reason: non-finite numbers, a non-positive
/// radius, an empty or inverted block, a polygon with fewer than 3 points, zero area or
/// self-intersecting edges.
std::string footprintProblem(const Footprint& footprint);

}  // namespace fleet_planner
