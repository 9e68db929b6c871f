// The orders of the parking plan's turns (parking_orders.h): who crosses whose target, and the
// three orders made from it.
#include "fleet_planner/solvers/lns/parking_orders.h"

#include <gtest/gtest.h>

#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

// Two rows of 12 cells. "a" drives row 0 end to end, over the target of "b"; "b" comes from
// row 1 and "c" drives a few cells of row 1: nobody's way covers a's or c's target.
World crossingWorld() {
  return World(freeMap(12, 2), {dot("a", {0, 0, 0}, {11, 0, 0}), dot("b", {0, 1, 0}, {5, 0, 0}),
                                dot("c", {11, 1, 2}, {8, 1, 2})});
}

StatePath straightWay(const SearchSpace& space, int a, int from_x, int to_x, int y, int heading) {
  StatePath way;
  const int step = to_x >= from_x ? 1 : -1;
  for (int x = from_x; x != to_x + step; x += step) way.push_back(space.graph(a).id({x, y, heading}));
  return way;
}

std::vector<StatePath> waysOf(const SearchSpace& space) {
  StatePath b = straightWay(space, 1, 0, 5, 1, 0);
  b.push_back(space.graph(1).id({5, 0, 0}));
  return {straightWay(space, 0, 0, 11, 0, 0), b, straightWay(space, 2, 11, 8, 1, 2)};
}

TEST(ParkingOrders, CountTheOtherRobotsWaysOverEachTarget) {
  const World w = crossingWorld();
  const SearchSpace space(allRobots(w));
  EXPECT_EQ(targetsCrossed(space, waysOf(space)), (std::vector<int>{0, 1, 0}));
  // A robot's own way over its own target does not count, nor does a way that passes by.
  std::vector<StatePath> ways = waysOf(space);
  ways[0] = straightWay(space, 0, 0, 4, 0, 0);
  EXPECT_EQ(targetsCrossed(space, ways), (std::vector<int>{0, 0, 0}));
  ways[2] = straightWay(space, 2, 11, 0, 1, 2);
  EXPECT_EQ(targetsCrossed(space, ways), (std::vector<int>{0, 0, 0})) << "c passes below b's target";
  ways[1] = straightWay(space, 1, 0, 11, 1, 0);
  EXPECT_EQ(targetsCrossed(space, ways), (std::vector<int>{0, 0, 1})) << "b drives over c's target";
}

TEST(ParkingOrders, AShortestWayRunsDownTheDistanceTableToTheTarget) {
  const World w(mapFromRows({"......", ".@@@@.", "......"}), {dot("a", {0, 0, 0}, {5, 2, 2}), dot("b", {3, 2, 2}, {1, 2, 2})});
  const SearchSpace space(allRobots(w));
  const StatePath way = shortestWay(space, 0);
  ASSERT_FALSE(way.empty());
  EXPECT_EQ(way.front(), space.start(0));
  EXPECT_EQ(way.back(), space.target(0));
  EXPECT_EQ(static_cast<int>(way.size()) - 1, space.distance(0, space.start(0)));
  for (std::size_t i = 1; i < way.size(); ++i) {
    const auto action = actionBetween(space.graph(0).pose(way[i - 1]), space.graph(0).pose(way[i]), {});
    ASSERT_TRUE(action.has_value()) << "step " << i;
    EXPECT_TRUE(space.allows(0, way[i - 1], *action)) << "step " << i;
  }
}

TEST(ParkingOrders, LongestFirstShortestFirstCrossedTargetsLast) {
  const World w = crossingWorld();
  const SearchSpace space(allRobots(w));
  ASSERT_LT(space.distance(2, space.start(2)), space.distance(1, space.start(1)));
  ASSERT_LT(space.distance(1, space.start(1)), space.distance(0, space.start(0)));
  const std::vector<int> longest_first = {0, 1, 2};
  EXPECT_EQ(targetsCrossed(space, {shortestWay(space, 0), shortestWay(space, 1), shortestWay(space, 2)}),
            (std::vector<int>{0, 1, 0}));
  EXPECT_EQ(parkingOrders(space, longest_first, 1), (std::vector<std::vector<int>>{{0, 1, 2}}));
  EXPECT_EQ(parkingOrders(space, longest_first, 3),
            (std::vector<std::vector<int>>{{0, 1, 2}, {2, 1, 0}, {2, 0, 1}}));
  // An order equal to an earlier one is made once.
  EXPECT_EQ(parkingOrders(space, {2, 1, 0}, 3), (std::vector<std::vector<int>>{{2, 1, 0}, {2, 0, 1}}));
  EXPECT_EQ(parkingOrders(space, {2, 0, 1}, 3), (std::vector<std::vector<int>>{{2, 0, 1}, {2, 1, 0}}));
}

}  // namespace
}  // namespace fleet_planner::test
