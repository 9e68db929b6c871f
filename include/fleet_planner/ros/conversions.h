#pragma once
/// convert(): ROS messages to core types and back. The only place where metres and radians in the
/// map frame meet cells and headings.
///
/// Grid frame: cell (x, y) has its lower corner at origin + resolution * (x, y), rotated by the
/// map's yaw, and the robot's origin sits at the cell's centre. Heading 0 = +x of the grid,
/// 1 = -x, 2 = +y, 3 = -y, i.e. yaw 0, pi, pi/2, -pi/2 relative to the map's yaw.
#include <optional>
#include <string>

#include <fleet_planner/RobotFootprint.h>
#include <geometry_msgs/Pose2D.h>
#include <nav_msgs/OccupancyGrid.h>

#include "fleet_planner/model/footprint.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/types.h"

namespace fleet_planner {

/// How occupancy values become blocked cells.
struct OccupancyPolicy {
  int occupied_threshold = 65;  ///< values >= this (0..100) are blocked
  bool unknown_is_free = false;  ///< -1 cells: free or blocked
};

/// The grid of an OccupancyGrid (row 0 at the origin, as in the message). Throws InvalidInput for
/// a zero size, a size that does not match the data, or a non-positive/non-finite resolution.
/// The origin's yaw is that of its orientation normalised (all zeros: no rotation).
GridMap convert(const nav_msgs::OccupancyGrid& grid, const OccupancyPolicy& policy);

/// A registry footprint (metres) in cells of `resolution` metres. Throws InvalidInput naming the
/// robot for an unknown type or an unusable shape (see footprintProblem()).
Footprint convert(const fleet_planner::RobotFootprint& footprint, double resolution);

/// How far a pose may be from a cell centre and a grid heading.
struct PoseTolerance {
  double position = 0.1;  ///< metres from the nearest cell centre
  double heading = 0.2;   ///< radians from the nearest grid heading
};

/// A map-frame pose snapped to the grid, or why it cannot be.
struct GridPoseFit {
  GridPose pose;  ///< the cell and the nearest grid heading
  /// The yaw in the grid's frame (radians) when it is more than the heading tolerance from every
  /// grid heading: the plan turns the robot in place from or to it.
  std::optional<double> yaw;
  std::string error;  ///< empty on success, e.g. "x is NaN", "(31.0, 2.0) is off the map ..."
  bool ok() const { return error.empty(); }
};

/// Largest |theta| of a pose, radians. Beyond it a yaw is noise rather than an angle (a client's
/// bug): at 1e20 rad neighbouring doubles are 16384 rad apart, so it would match a grid heading
/// by chance.
constexpr double kMaxAbsYaw = 1e6;

/// Why a pose's numbers cannot be a pose, whatever the map: "x is nan", "theta is inf",
/// "theta 1e+20 rad is not an angle (|theta| must be at most 1e+06 rad)"; empty if usable.
std::string poseValueProblem(const geometry_msgs::Pose2D& pose);

/// The grid state nearest to `pose` (its cell, the nearest heading, and the yaw itself when it is
/// beyond the heading tolerance); an error if poseValueProblem() finds one, the point is off the
/// map, or it is farther than the position tolerance from the cell centre.
GridPoseFit toGridPose(const GridMap& map, const geometry_msgs::Pose2D& pose, const PoseTolerance& tolerance);

/// The map-frame pose of a grid state (the centre of its cell, its heading's yaw).
geometry_msgs::Pose2D toPose2D(const GridMap& map, const GridPose& pose);

/// Angle wrapped to (-pi, pi].
double wrapAngle(double angle);

}  // namespace fleet_planner
