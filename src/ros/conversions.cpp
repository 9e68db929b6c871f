#include "fleet_planner/ros/conversions.h"

#include <cmath>
#include <cstdio>

#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

namespace {

constexpr double kPi = 3.14159265358979323846;
/// Yaw of each heading in the grid frame.
constexpr double kHeadingYaw[kHeadings] = {0.0, kPi, kPi / 2, -kPi / 2};

/// "%.3f", or "%.6g" for values too large to print that way (1e300 would be cut off).
std::string metres(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), std::abs(v) < 1e9 ? "%.3f" : "%.6g", v);
  return buf;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%g", v);
  return buf;
}

}  // namespace

double wrapAngle(double angle) {
  double a = std::remainder(angle, 2 * kPi);
  if (a <= -kPi) a += 2 * kPi;
  return a;
}

GridMap convert(const nav_msgs::OccupancyGrid& grid, const OccupancyPolicy& policy) {
  const auto& info = grid.info;
  if (info.width == 0 || info.height == 0) throw InvalidInput("map: width and height must be positive");
  if (!(info.resolution > 0) || !std::isfinite(info.resolution)) {
    throw InvalidInput("map: resolution must be positive (got " + std::to_string(info.resolution) + ")");
  }
  const std::size_t cells = static_cast<std::size_t>(info.width) * info.height;
  if (grid.data.size() != cells) {
    throw InvalidInput("map: " + std::to_string(info.width) + " x " + std::to_string(info.height) +
                       " needs " + std::to_string(cells) + " cells, got " + std::to_string(grid.data.size()));
  }
  std::vector<std::uint8_t> blocked(cells);
  for (std::size_t i = 0; i < cells; ++i) {
    const int v = grid.data[i];
    blocked[i] = v < 0 ? !policy.unknown_is_free : v >= policy.occupied_threshold;
  }
  const auto& q = info.origin.orientation;
  MapOrigin origin;
  origin.x = info.origin.position.x;
  origin.y = info.origin.position.y;
  // The yaw of q / |q|: this form does not assume a unit quaternion (1 - 2 (y^2 + z^2) does, and
  // gave (0, 0, 1, 1) a yaw of 116.6 degrees instead of 90). All zeros, as tools that leave the
  // orientation unset publish it, is atan2(0, 0) = 0: no rotation.
  origin.yaw = std::atan2(2.0 * (q.w * q.z + q.x * q.y), q.w * q.w + q.x * q.x - q.y * q.y - q.z * q.z);
  return GridMap(static_cast<int>(info.width), static_cast<int>(info.height), std::move(blocked),
                 info.resolution, origin);
}

Footprint convert(const fleet_planner::RobotFootprint& msg, double resolution) {
  const std::string who = "robot '" + msg.robot_id + "'";
  Footprint f;
  switch (msg.type) {
    case fleet_planner::RobotFootprint::CIRCLE:
      f = Footprint::circle(msg.radius / resolution);
      break;
    case fleet_planner::RobotFootprint::BLOCK:
      f = Footprint::block(msg.min_x / resolution, msg.min_y / resolution, msg.max_x / resolution,
                           msg.max_y / resolution);
      break;
    case fleet_planner::RobotFootprint::POLYGON: {
      std::vector<Eigen::Vector2d> points;
      for (const auto& p : msg.points) points.emplace_back(p.x / resolution, p.y / resolution);
      f = Footprint::polygon(std::move(points));
      break;
    }
    default:
      throw InvalidInput(who + ": footprint type " + std::to_string(msg.type) +
                         " is not CIRCLE (0), BLOCK (1) or POLYGON (2)");
  }
  const std::string problem = footprintProblem(f);
  if (!problem.empty()) throw InvalidInput(who + ": footprint: " + problem);
  return f;
}

std::string poseValueProblem(const geometry_msgs::Pose2D& pose) {
  if (!std::isfinite(pose.x)) return "x is " + number(pose.x);
  if (!std::isfinite(pose.y)) return "y is " + number(pose.y);
  if (!std::isfinite(pose.theta)) return "theta is " + number(pose.theta);
  if (std::abs(pose.theta) > kMaxAbsYaw) {
    return "theta " + number(pose.theta) + " rad is not an angle (|theta| must be at most " + number(kMaxAbsYaw) +
           " rad)";
  }
  return {};
}

GridPoseFit toGridPose(const GridMap& map, const geometry_msgs::Pose2D& pose, const PoseTolerance& tolerance) {
  GridPoseFit fit;
  fit.error = poseValueProblem(pose);
  if (!fit.ok()) return fit;

  const MapOrigin& o = map.origin();
  const double c = std::cos(o.yaw), s = std::sin(o.yaw);
  const double dx = pose.x - o.x, dy = pose.y - o.y;
  const double gx = (c * dx + s * dy) / map.resolution();  // in cells, grid frame
  const double gy = (-s * dx + c * dy) / map.resolution();
  const std::string at = "(" + metres(pose.x) + ", " + metres(pose.y) + ")";
  if (!(gx >= 0 && gy >= 0 && gx < map.width() && gy < map.height())) {  // NaN-proof
    fit.error = at + " is off the map (" + std::to_string(map.width()) + " x " + std::to_string(map.height()) +
                " cells of " + metres(map.resolution()) + " m)";
    return fit;
  }
  fit.pose.x = static_cast<int>(std::floor(gx));
  fit.pose.y = static_cast<int>(std::floor(gy));
  const double off = std::hypot(gx - (fit.pose.x + 0.5), gy - (fit.pose.y + 0.5)) * map.resolution();
  if (off > tolerance.position + 1e-9) {
    const auto centre = toPose2D(map, fit.pose);
    fit.error = at + " is " + metres(off) + " m from the nearest cell centre (" + metres(centre.x) + ", " +
                metres(centre.y) + "); position_tolerance is " + metres(tolerance.position) + " m";
    return fit;
  }
  const double yaw = wrapAngle(pose.theta - o.yaw);
  double best = 1e9;
  for (int h = 0; h < kHeadings; ++h) {
    const double d = std::abs(wrapAngle(yaw - kHeadingYaw[h]));
    if (d < best) best = d, fit.pose.heading = h;
  }
  if (best > tolerance.heading + 1e-9) fit.yaw = yaw;  // any yaw: a turn in place connects it
  return fit;
}

geometry_msgs::Pose2D toPose2D(const GridMap& map, const GridPose& pose) {
  const MapOrigin& o = map.origin();
  const double c = std::cos(o.yaw), s = std::sin(o.yaw);
  const double gx = (pose.x + 0.5) * map.resolution(), gy = (pose.y + 0.5) * map.resolution();
  geometry_msgs::Pose2D out;
  out.x = o.x + c * gx - s * gy;
  out.y = o.y + s * gx + c * gy;
  out.theta = wrapAngle(o.yaw + kHeadingYaw[validHeading(pose.heading) ? pose.heading : 0]);
  return out;
}

}  // namespace fleet_planner
