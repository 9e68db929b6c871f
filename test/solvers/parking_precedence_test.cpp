// Who must park before whom (parking_precedence.h): a robot whose target shuts another robot's
// start or target in a dead end parks after it; the orders keep that with the least change.
#include "fleet_planner/solvers/lns/parking_precedence.h"

#include <gtest/gtest.h>

#include "fleet_planner/solvers/lns/parking_orders.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

// A room of 12 x 5 cells with a dead-end street one cell wide going east from its middle row:
// cells x = 12..19 of row 2. "deep" parks at the street's end, "mouth" just inside the street,
// "out" starts at the street's end and leaves for the room, "free" crosses the room.
std::vector<std::string> streetRows() {
  std::vector<std::string> rows(5, std::string(12, '.') + std::string(8, '@'));
  rows[2] = std::string(20, '.');
  return rows;
}

World streetWorld() {
  return World(mapFromRows(streetRows()),
               {dot("deep", {0, 0, 0}, {19, 2, 0}), dot("mouth", {0, 4, 0}, {13, 2, 0}),
                dot("out", {18, 2, 2}, {1, 1, 2}), dot("free", {2, 0, 0}, {6, 2, 0})});
}

std::vector<StatePath> shortestWays(const SearchSpace& space) {
  std::vector<StatePath> ways(space.numAgents());
  for (int a = 0; a < space.numAgents(); ++a) ways[a] = shortestWay(space, a);
  return ways;
}

TEST(ParkingPrecedence, ATargetInADeadEndStreetShutsTheRobotsBeyondIt) {
  const World w = streetWorld();
  const SearchSpace space(allRobots(w));
  // deep's way in and out's way out both pass mouth's target; nobody else's target closes a way.
  EXPECT_EQ(wayAroundTarget(space, 0, 1, 100'000), WayAround::Closed);
  EXPECT_EQ(wayAroundTarget(space, 2, 1, 100'000), WayAround::Closed);
  EXPECT_EQ(wayAroundTarget(space, 0, 3, 100'000), WayAround::Open) << "free parks in the room: deep goes round";
  EXPECT_EQ(wayAroundTarget(space, 3, 1, 100'000), WayAround::Open) << "free's way does not need the street";
  const std::vector<std::vector<int>> before = parkingPrecedence(space, shortestWays(space), 100'000);
  EXPECT_EQ(before, (std::vector<std::vector<int>>{{}, {0, 2}, {}, {}}));
}

TEST(ParkingPrecedence, TheDeadEndSideIsExhaustedWithinAboutItsSize) {
  // The room made large (60 x 41 cells, about 10,000 states), the street as before: deciding that
  // mouth's target shuts deep in takes about the street's states on the search from deep's target,
  // while the search from deep's start still has most of the room ahead of it.
  std::vector<std::string> rows(41, std::string(60, '.') + std::string(8, '@'));
  rows[20] = std::string(68, '.');
  const World w(mapFromRows(rows), {dot("deep", {0, 0, 0}, {67, 20, 0}), dot("mouth", {0, 40, 0}, {61, 20, 0})});
  const SearchSpace space(allRobots(w));
  EXPECT_EQ(wayAroundTarget(space, 0, 1, 200), WayAround::Closed);
  EXPECT_EQ(wayAroundTarget(space, 0, 1, 10), WayAround::Unknown) << "too few expansions to tell";
}

TEST(ParkingPrecedence, OrdersChangeOnlyWhereAPrecedenceAsks) {
  const std::vector<std::vector<int>> before = {{}, {0, 2}, {}, {}};
  EXPECT_EQ(honourPrecedence({1, 3, 0, 2}, before), (std::vector<int>{3, 0, 2, 1}));
  EXPECT_EQ(honourPrecedence({0, 2, 1, 3}, before), (std::vector<int>{0, 2, 1, 3}));
  EXPECT_EQ(honourPrecedence({3, 2, 1, 0}, before), (std::vector<int>{3, 2, 0, 1}));
  // Agents outside the order do not hold anybody back.
  EXPECT_EQ(honourPrecedence({1, 3}, before), (std::vector<int>{1, 3}));
  // A cycle (a pair that cannot both park): the earliest agent left goes first.
  EXPECT_EQ(honourPrecedence({2, 0, 1}, {{1}, {0}, {}}), (std::vector<int>{2, 0, 1}));
}

TEST(ParkingPrecedence, TheFirstParkingOrderHonoursThePrecedences) {
  const World w = streetWorld();
  const SearchSpace space(allRobots(w));
  const std::vector<std::vector<int>> orders = parkingOrders(space, {1, 3, 0, 2}, 3, 100'000);
  ASSERT_FALSE(orders.empty());
  EXPECT_EQ(orders[0], (std::vector<int>{3, 0, 2, 1})) << "mouth parks after deep and out";
  EXPECT_EQ(parkingOrders(space, {1, 3, 0, 2}, 1, 0), (std::vector<std::vector<int>>{{1, 3, 0, 2}}))
      << "without precedences the order is kept";
}

}  // namespace
}  // namespace fleet_planner::test
