// Bad instances get typed errors naming the robot; the solvability pre-check names the reason.
#include "fleet_planner/model/instance_check.h"

#include <gtest/gtest.h>

#include "fleet_planner/runtime/errors.h"
#include "test_maps.h"
#include "test_robots.h"

namespace fleet_planner {
namespace {

using test::freeMap;
using test::mapFromRows;

Robot robot(const std::string& id, Footprint f, GridPose start, GridPose target) {
  Robot r = test::makeRobot(id, std::move(f), start, target);
  r.source = "fleet.txt:" + id;
  return r;
}

std::string errorOf(const GridMap& map, std::vector<Robot> robots) {
  Instance instance;
  instance.robots = std::move(robots);
  try {
    validateInstance(map, instance);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(ValidateInstance, AcceptsAGoodInstance) {
  EXPECT_EQ(errorOf(freeMap(6, 6), {robot("7", Footprint::circle(1.0), {1, 1, 0}, {4, 4, 2})}), "");
}

TEST(ValidateInstance, NamesTheRobotAndTheReason) {
  const GridMap map = mapFromRows({"......", "......", "..@...", "......", "......", "......"});
  auto err = errorOf(map, {robot("3", Footprint::circle(0.4), {9, 1, 0}, {1, 1, 0})});
  EXPECT_NE(err.find("robot '3' (fleet.txt:3)"), std::string::npos) << err;
  EXPECT_NE(err.find("off the"), std::string::npos) << err;
  err = errorOf(map, {robot("4", Footprint::circle(1.0), {4, 4, 0}, {2, 3, 0})});
  EXPECT_NE(err.find("target"), std::string::npos) << err;
  EXPECT_NE(err.find("blocked cell (2,2)"), std::string::npos) << err;
  err = errorOf(map, {robot("5", Footprint::circle(1.0), {0, 3, 0}, {4, 4, 0})});
  EXPECT_NE(err.find("leaves the map"), std::string::npos) << err;
  err = errorOf(map, {robot("6", Footprint::circle(0.4), {1, 1, 4}, {4, 4, 0})});
  EXPECT_NE(err.find("heading"), std::string::npos) << err;
}

TEST(ValidateInstance, FootprintLargerThanTheMap) {
  const auto err = errorOf(freeMap(4, 4), {robot("big", Footprint::circle(3.0), {2, 2, 0}, {2, 2, 0})});
  EXPECT_NE(err.find("larger than the 4 x 4 map"), std::string::npos) << err;
}

TEST(ValidateInstance, BadFootprintsAndIds) {
  const GridMap map = freeMap(6, 6);
  auto err = errorOf(map, {robot("n", Footprint::circle(std::nan("")), {1, 1, 0}, {4, 4, 0})});
  EXPECT_NE(err.find("robot 'n'"), std::string::npos) << err;
  EXPECT_NE(err.find("finite"), std::string::npos) << err;
  err = errorOf(map, {robot("z", Footprint::block(0.5, -1, -0.5, 1), {1, 1, 0}, {4, 4, 0})});
  EXPECT_NE(err.find("min_x < max_x"), std::string::npos) << err;
  err = errorOf(map, {robot("d", Footprint::circle(0.4), {1, 1, 0}, {4, 4, 0}),
                      robot("d", Footprint::circle(0.4), {2, 1, 0}, {3, 4, 0})});
  EXPECT_NE(err.find("duplicate"), std::string::npos) << err;
}

TEST(Solvability, ReportsUnreachableTargetsAndOverlaps) {
  // The wall splits the map; robot 'c' cannot cross it, 'a' and 'b' start on top of each other.
  const GridMap map = mapFromRows({"...@...", "...@...", "...@..."});
  Instance instance;
  instance.robots = {robot("a", Footprint::circle(0.4), {0, 0, 0}, {2, 2, 0}),
                     robot("b", Footprint::circle(0.6), {0, 1, 0}, {1, 2, 0}),
                     robot("c", Footprint::circle(0.4), {5, 0, 0}, {0, 2, 0})};
  std::vector<Footprint> fps;
  for (const auto& r : instance.robots) fps.push_back(r.footprint);
  const FleetGraphs graphs(map, fps);
  const SolvabilityReport report = checkSolvability(instance, graphs);
  ASSERT_FALSE(report.solvable());
  const std::string text = report.summary();
  EXPECT_NE(text.find("robot 'c' (fleet.txt:c): target (0,2,0) is not reachable"), std::string::npos) << text;
  EXPECT_NE(text.find("robot 'a' (fleet.txt:a): start overlaps the start of robot 'b'"), std::string::npos) << text;
  EXPECT_NE(text.find("target overlaps the target of robot 'b'"), std::string::npos) << text;
  // b (a plus shape) cannot even stand at its start: its arms leave the map.
  EXPECT_NE(text.find("robot 'b' (fleet.txt:b): start (0,1,0) is not a valid state"), std::string::npos) << text;
}

TEST(SelectMixed, InterleavesCirclesAndBlocks) {
  Instance pool;
  for (int i = 0; i < 3; ++i) pool.robots.push_back(robot("c" + std::to_string(i), Footprint::circle(0.5), {}, {}));
  for (int i = 0; i < 5; ++i)
    pool.robots.push_back(robot("b" + std::to_string(i), Footprint::block(-1, -1, 1, 1), {}, {}));
  auto ids = [](const Instance& in) {
    std::string s;
    for (const auto& r : in.robots) s += r.id + " ";
    return s;
  };
  EXPECT_EQ(ids(selectMixed(pool, 1)), "c0 ");
  EXPECT_EQ(ids(selectMixed(pool, 4)), "c0 b0 c1 b1 ");
  EXPECT_EQ(ids(selectMixed(pool, 5)), "c0 b0 c1 b1 c2 ");
  // Circles run out: blocks fill the rest.
  EXPECT_EQ(ids(selectMixed(pool, 8)), "c0 b0 c1 b1 c2 b2 b3 b4 ");
  EXPECT_THROW(selectMixed(pool, 9), InvalidInput);
  EXPECT_THROW(selectMixed(pool, 0), InvalidInput);
}

}  // namespace
}  // namespace fleet_planner
