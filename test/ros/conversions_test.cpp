// Metres and radians <-> cells and headings, and occupancy values -> blocked cells.
#include <gtest/gtest.h>

#include <cmath>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/ros/conversions.h"
#include "ros_test_util.h"

namespace fleet_planner::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

geometry_msgs::Pose2D pose(double x, double y, double theta) {
  geometry_msgs::Pose2D p;
  p.x = x, p.y = y, p.theta = theta;
  return p;
}

TEST(OccupancyConversion, ThresholdAndUnknownPolicy) {
  nav_msgs::OccupancyGrid grid = occupancyGrid(4, 3, 0.5, 1.0, 2.0);
  grid.data = {0, 64, 65, 100, -1, 10, 90, 0, 0, 0, 0, 0};
  const GridMap map = convert(grid, OccupancyPolicy{65, false});
  EXPECT_EQ(map.width(), 4);
  EXPECT_EQ(map.height(), 3);
  EXPECT_DOUBLE_EQ(map.resolution(), 0.5);
  EXPECT_DOUBLE_EQ(map.origin().x, 1.0);
  EXPECT_FALSE(map.blocked(0, 0));
  EXPECT_FALSE(map.blocked(1, 0));  // 64 < 65
  EXPECT_TRUE(map.blocked(2, 0));
  EXPECT_TRUE(map.blocked(3, 0));
  EXPECT_TRUE(map.blocked(0, 1));  // unknown: obstacle
  EXPECT_TRUE(map.blocked(2, 1));
  const GridMap lenient = convert(grid, OccupancyPolicy{95, true});
  EXPECT_FALSE(lenient.blocked(0, 1));  // unknown: free
  EXPECT_FALSE(lenient.blocked(2, 0));  // 65 < 95
  EXPECT_TRUE(lenient.blocked(3, 0));
}

TEST(OccupancyConversion, RejectsBrokenGrids) {
  nav_msgs::OccupancyGrid grid = occupancyGrid(4, 3, 0.5, 0, 0);
  grid.data.resize(5);
  EXPECT_THROW(convert(grid, {}), InvalidInput);
  grid = occupancyGrid(4, 3, 0.5, 0, 0);
  grid.info.resolution = 0;
  EXPECT_THROW(convert(grid, {}), InvalidInput);
  grid.info.width = 0;
  EXPECT_THROW(convert(grid, {}), InvalidInput);
}

TEST(PoseConversion, RoundTripsEveryHeadingOnARotatedMap) {
  nav_msgs::OccupancyGrid grid = occupancyGrid(10, 8, 0.2, 3.0, -1.0);
  const double yaw = 0.3;
  grid.info.origin.orientation.z = std::sin(yaw / 2);
  grid.info.origin.orientation.w = std::cos(yaw / 2);
  const GridMap map = convert(grid, {});
  EXPECT_NEAR(map.origin().yaw, yaw, 1e-9);
  for (int h = 0; h < kHeadings; ++h) {
    const GridPose cell{6, 3, h};
    const auto world = toPose2D(map, cell);
    const GridPoseFit fit = toGridPose(map, world, PoseTolerance{0.01, 0.01});
    ASSERT_TRUE(fit.ok()) << fit.error;
    EXPECT_EQ(fit.pose, cell);
  }
  // Heading 2 (+y of the grid) is yaw + pi/2 in the map frame.
  EXPECT_NEAR(toPose2D(map, {0, 0, 2}).theta, yaw + kPi / 2, 1e-9);
  // Cell (0, 0)'s centre is half a cell from the origin along the rotated axes.
  const auto c = toPose2D(map, {0, 0, 0});
  EXPECT_NEAR(c.x, 3.0 + 0.1 * std::cos(yaw) - 0.1 * std::sin(yaw), 1e-6);  // resolution is a float32
  EXPECT_NEAR(c.y, -1.0 + 0.1 * std::sin(yaw) + 0.1 * std::cos(yaw), 1e-6);
}

TEST(OccupancyConversion, OriginYawFromAnyQuaternionScale) {
  auto grid = occupancyGrid(10, 8, 0.5, 0.0, 0.0);
  grid.info.origin.orientation.z = 1.0;  // (0, 0, 1, 1): a quarter turn, not normalised
  grid.info.origin.orientation.w = 1.0;
  EXPECT_NEAR(convert(grid, {}).origin().yaw, kPi / 2, 1e-12);
  grid.info.origin.orientation.z = 0.0;  // all zeros: an orientation left unset
  grid.info.origin.orientation.w = 0.0;
  EXPECT_EQ(convert(grid, {}).origin().yaw, 0.0);
  grid.info.origin.orientation.w = NAN;
  EXPECT_THROW(convert(grid, {}), InvalidInput);
}

TEST(PoseConversion, SnapsWithinTolerancesAndExplainsOtherwise) {
  const GridMap map = convert(occupancyGrid(10, 8, 0.5, 0.0, 0.0), {});
  const PoseTolerance tolerance{0.1, 0.2};
  GridPoseFit fit = toGridPose(map, pose(1.30, 0.80, -kPi / 2 + 0.1), tolerance);
  ASSERT_TRUE(fit.ok()) << fit.error;
  EXPECT_EQ(fit.pose, (GridPose{2, 1, 3}));
  fit = toGridPose(map, pose(1.25, 0.75, 3.1), tolerance);
  ASSERT_TRUE(fit.ok()) << fit.error;
  EXPECT_EQ(fit.pose.heading, 1);

  EXPECT_NE(toGridPose(map, pose(1.45, 0.75, 0), tolerance).error.find("position_tolerance"), std::string::npos);
  // Beyond the heading tolerance a yaw is kept (the plan turns from or to it), on the nearest heading.
  fit = toGridPose(map, pose(1.25, 0.75, 0.7), tolerance);
  ASSERT_TRUE(fit.ok()) << fit.error;
  ASSERT_TRUE(fit.yaw.has_value());
  EXPECT_NEAR(*fit.yaw, 0.7, 1e-12);
  EXPECT_EQ(fit.pose.heading, 0);
  EXPECT_FALSE(toGridPose(map, pose(1.25, 0.75, 0.1), tolerance).yaw.has_value());
  EXPECT_NE(toGridPose(map, pose(5.01, 0.75, 0), tolerance).error.find("off the map"), std::string::npos);
  EXPECT_NE(toGridPose(map, pose(-0.01, 0.75, 0), tolerance).error.find("off the map"), std::string::npos);
  EXPECT_EQ(toGridPose(map, pose(NAN, 0.75, 0), tolerance).error, "x is nan");
  EXPECT_EQ(toGridPose(map, pose(1.25, 0.75, INFINITY), tolerance).error, "theta is inf");
  EXPECT_EQ(toGridPose(map, pose(1.25, -INFINITY, 0), tolerance).error, "y is -inf");
  EXPECT_NE(toGridPose(map, pose(1.25, 0.75, -1e20), tolerance).error.find("theta -1e+20 rad is not an angle"),
            std::string::npos);
  EXPECT_EQ(toGridPose(map, pose(1e300, 0.75, 0), tolerance).error.rfind("(1e+300, 0.750) is off the map", 0), 0u);
}

TEST(PoseConversion, OffTheMapEvenWhenTheArithmeticOverflows) {
  // Origin and pose at opposite ends of the doubles: the offset overflows to inf and 0 * inf is
  // NaN in one coordinate; no NaN may slip through the bounds check as a cell index.
  const GridMap map = convert(occupancyGrid(10, 8, 0.5, 0.0, -1.7e308), {});
  const GridPoseFit fit = toGridPose(map, pose(1.25, 1.7e308, 0), PoseTolerance{0.1, 0.2});
  EXPECT_NE(fit.error.find("off the map"), std::string::npos) << fit.error;
}

TEST(FootprintConversion, MetresBecomeCells) {
  const Footprint circle = convert(circleFootprint("a", 0.3), 0.2);
  EXPECT_EQ(circle.kind, Footprint::Kind::Circle);
  EXPECT_NEAR(circle.radius, 1.5, 1e-12);
  const Footprint block = convert(blockFootprint("b", -0.2, 0.6, -0.4, 0.4), 0.2);
  EXPECT_NEAR(block.min_x, -1.0, 1e-12);
  EXPECT_NEAR(block.max_x, 3.0, 1e-12);
  EXPECT_NEAR(block.max_y, 2.0, 1e-12);
  fleet_planner::RobotFootprint poly;
  poly.robot_id = "p";
  poly.type = fleet_planner::RobotFootprint::POLYGON;
  for (auto [x, y] : {std::pair{0.4, 0.0}, {-0.2, 0.2}, {-0.2, -0.2}}) {
    geometry_msgs::Point32 p;
    p.x = x, p.y = y;
    poly.points.push_back(p);
  }
  const Footprint triangle = convert(poly, 0.2);
  ASSERT_EQ(triangle.points.size(), 3u);
  EXPECT_NEAR(triangle.points[0].x(), 2.0, 1e-6);
}

TEST(FootprintConversion, BadFootprintsNameTheRobot) {
  auto bad = circleFootprint("wobbly", -1.0);
  try {
    convert(bad, 0.2);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("'wobbly'"), std::string::npos) << e.what();
  }
  bad.type = 7;
  EXPECT_THROW(convert(bad, 0.2), InvalidInput);
  fleet_planner::RobotFootprint line;
  line.type = fleet_planner::RobotFootprint::POLYGON;
  line.points.resize(2);
  EXPECT_THROW(convert(line, 0.2), InvalidInput);
}

}  // namespace
}  // namespace fleet_planner::test
