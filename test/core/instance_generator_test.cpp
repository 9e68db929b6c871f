// The random instance generator: the paper's distribution, valid and connected placements,
// and the same instance for the same seed.
#include "fleet_planner/io/instance_generator.h"

#include <gtest/gtest.h>

#include <cmath>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/model/instance_check.h"
#include "test_maps.h"
#include "test_robots.h"

namespace fleet_planner {
namespace {

bool isTenth(double v) { return std::abs(v * 10 - std::round(v * 10)) < 1e-9; }

TEST(InstanceGenerator, PaperDistributionValidAndConnected) {
  // 40 x 30 with a few walls: room for eight robots of up to 5 x 5 cells.
  std::vector<std::string> rows(30, std::string(40, '.'));
  for (int x = 5; x < 30; ++x) rows[10][x] = '@';
  for (int y = 15; y < 28; ++y) rows[y][20] = '@';
  for (int y = 2; y < 6; ++y) rows[y].replace(30, 4, "@@@@");
  const GridMap map = test::mapFromRows(rows);
  GeneratorOptions options;
  options.robots = 8;
  options.seed = 11;
  const Instance instance = generateInstance(map, options);
  ASSERT_EQ(instance.robots.size(), 8u);
  std::vector<Footprint> fps;
  for (std::size_t i = 0; i < instance.robots.size(); ++i) {
    const Footprint& f = instance.robots[i].footprint;
    fps.push_back(f);
    if (i % 2 == 0) {
      ASSERT_EQ(f.kind, Footprint::Kind::Circle);
      EXPECT_TRUE(f.radius >= 0.4 && f.radius <= 2.0 && isTenth(f.radius)) << f.radius;
    } else {
      ASSERT_EQ(f.kind, Footprint::Kind::Block);
      EXPECT_TRUE(f.min_x >= -2.0 && f.min_x <= -0.2 && isTenth(f.min_x)) << f.min_x;
      EXPECT_TRUE(f.max_x >= 0.2 && f.max_x <= 2.0 && isTenth(f.max_x)) << f.max_x;
      EXPECT_TRUE(f.max_y >= 0.2 && f.max_y <= 2.0 && isTenth(f.max_y)) << f.max_y;
      EXPECT_EQ(f.min_y, -f.max_y);
    }
  }
  EXPECT_NO_THROW(validateInstance(map, instance));
  const FleetGraphs graphs(map, fps);
  const SolvabilityReport report = checkSolvability(instance, graphs);
  EXPECT_TRUE(report.solvable()) << report.summary();
}

TEST(InstanceGenerator, SameSeedSameInstanceOtherSeedOther) {
  const GridMap map = test::freeMap(30, 30);
  GeneratorOptions options;
  options.robots = 10;
  options.seed = 5;
  const Instance a = generateInstance(map, options), b = generateInstance(map, options);
  options.seed = 6;
  const Instance c = generateInstance(map, options);
  bool all_same = true, any_diff = false;
  for (int i = 0; i < 10; ++i) {
    all_same &= a.robots[i].start == b.robots[i].start && a.robots[i].target == b.robots[i].target &&
                a.robots[i].footprint == b.robots[i].footprint;
    any_diff |= a.robots[i].start != c.robots[i].start || !(a.robots[i].footprint == c.robots[i].footprint);
  }
  EXPECT_TRUE(all_same);
  EXPECT_TRUE(any_diff);
}

TEST(InstanceGenerator, FullMapGivesAClearError) {
  GeneratorOptions options;
  options.robots = 40;
  options.attempts_per_robot = 200;
  try {
    generateInstance(test::freeMap(8, 8), options);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("could not place robot"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fleet_planner

namespace fleet_planner {
namespace {

TEST(InstanceGenerator, PolygonShareMakesValidPolygonsAndStillPlacesEveryRobot) {
  const GridMap map = test::freeMap(30, 30);
  GeneratorOptions options;
  options.robots = 12;
  options.seed = 3;
  options.polygon_share = 1.0;  // every non-circle robot a polygon
  const Instance instance = generateInstance(map, options);
  ASSERT_EQ(instance.robots.size(), 12u);
  for (std::size_t i = 0; i < instance.robots.size(); ++i) {
    const Footprint& f = instance.robots[i].footprint;
    if (i % 2 == 0) {
      EXPECT_EQ(f.kind, Footprint::Kind::Circle);
      continue;
    }
    ASSERT_EQ(f.kind, Footprint::Kind::Polygon);
    EXPECT_GE(f.points.size(), 3u);
    EXPECT_LE(f.points.size(), 8u);
    EXPECT_EQ(footprintProblem(f), "");
    for (const auto& p : f.points) EXPECT_TRUE(isTenth(p.x()) && isTenth(p.y())) << p.transpose();
  }
  EXPECT_NO_THROW(validateInstance(map, instance));
  const FleetGraphs graphs(map, test::footprintsOf(instance));
  EXPECT_TRUE(checkSolvability(instance, graphs).solvable());
}

TEST(InstanceGenerator, PolygonShareOutsideZeroToOneIsRefused) {
  GeneratorOptions options;
  options.polygon_share = 1.5;
  EXPECT_THROW(generateInstance(test::freeMap(10, 10), options), InvalidInput);
}

}  // namespace
}  // namespace fleet_planner
