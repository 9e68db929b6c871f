// The plan made one robot at a time with the robots in its way pushed into pockets
// (parking_plan.h), alone and as LA-LNS's first plan: every plan passes the validator.
#include "fleet_planner/solvers/lns/parking_plan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/solvers/lns/la_lns.h"
#include "fleet_planner/solvers/search/agent_conflicts.h"
#include "fleet_planner/solvers/search/solve_common.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

std::vector<int> everyAgent(const SearchSpace& space) {
  std::vector<int> order(space.numAgents());
  for (int a = 0; a < space.numAgents(); ++a) order[a] = a;
  return order;
}

// The parking plan of every agent of `space`, in index order; `expansions` gets its count.
std::optional<ParkingPlan> planAll(const SearchSpace& space, long long& expansions) {
  expansions = 0;
  return parkingPlan(space, everyAgent(space), Deadline::in(5.0), ParkingPlanOptions{}, expansions);
}

bool visits(const Path& path, const GridPose& cell) {
  return std::any_of(path.begin(), path.end(),
                     [&](const GridPose& p) { return p.x == cell.x && p.y == cell.y; });
}

// A corridor 14 cells long with a pocket one cell deep below x = 6: "a" drives the corridor
// east; "b" stands at its target in the middle of it. "a" gets past only if b backs into the
// pocket and comes back.
World corridorWorld() {
  return World(mapFromRows({"..............", "@@@@@@.@@@@@@@"}),
               {dot("a", {0, 0, 0}, {13, 0, 0}), dot("b", {9, 0, 0}, {9, 0, 0})});
}

TEST(ParkingPlan, PushesTheRobotStandingOnTheWayIntoAPocketAndBringsItBack) {
  const World w = corridorWorld();
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  long long expansions = 0;
  const auto plan = planAll(space, expansions);
  ASSERT_TRUE(plan.has_value());
  EXPECT_EQ(plan->robots_home, 2);
  EXPECT_GT(expansions, 0);
  const ValidationResult v = validateStatePaths(w, sub, space, plan->paths);
  EXPECT_TRUE(v.valid()) << violationName(v.violation.kind);
  const std::vector<Path> paths = toPosePaths(space, plan->paths);
  EXPECT_TRUE(visits(paths[1], {6, 1, 0})) << "b never parked in the pocket";
  EXPECT_EQ(paths[1].back(), (GridPose{9, 0, 0}));
  // Same input, same plan.
  const auto again = planAll(space, expansions);
  ASSERT_TRUE(again.has_value());
  EXPECT_EQ(again->paths, plan->paths);
}

TEST(ParkingPlan, GivesUpARobotWithNoWayAndKeepsTheOthersPlan) {
  // Two robots trading the ends of a corridor without a pocket: neither gets past the other.
  // "c" has its own way in the row above, which the other two never need.
  const World w(mapFromRows({"..............", "@@@@@@@@@@@@@@", ".............."}),
                {dot("a", {0, 0, 0}, {13, 0, 0}), dot("b", {13, 0, 2}, {0, 0, 2}),
                 dot("c", {0, 2, 0}, {13, 2, 0})});
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  long long expansions = 0;
  const auto plan = planAll(space, expansions);
  ASSERT_TRUE(plan.has_value());
  EXPECT_TRUE(plan->home[2]);
  EXPECT_FALSE(plan->home[0] || plan->home[1]) << "each stands on the other's target";
  EXPECT_EQ(plan->robots_home, 1);
  EXPECT_FALSE(firstConflict(space, plan->paths).has_value());
  for (int a = 0; a < space.numAgents(); ++a) EXPECT_EQ(plan->paths[a].front(), space.start(a));
}

// A robot of another subproblem ("p") drives up from below into the door of a small room off
// the corridor and parks there for good. "b", pushed off a's way, must not take a pocket in the
// room: after p has closed the door it could never get home. It takes the pocket at x = 3.
TEST(ParkingPlan, TakesNoPocketThatARobotParkedForGoodCutsOffFromHome) {
  const World w(mapFromRows({"..............", "@@@.@@@@@.@@@@", "@@@@@@@@...@@@", "@@@@@@@@@.@@@@"}),
                {dot("a", {0, 0, 0}, {13, 0, 0}), dot("b", {9, 0, 0}, {9, 0, 0}),
                 dot("p", {9, 3, 3}, {9, 1, 3})});
  Subproblem sub = allRobots(w);
  sub.robots = {0, 1};
  MovingObstacle p;
  p.robot = 2;
  p.path.assign(9, GridPose{9, 3, 3});
  p.path.push_back({9, 2, 3});
  p.path.push_back({9, 1, 3});
  sub.moving.push_back(p);
  const SearchSpace space(sub);
  long long expansions = 0;
  const auto plan = planAll(space, expansions);
  ASSERT_TRUE(plan.has_value());
  EXPECT_EQ(plan->robots_home, 2) << "b was trapped in the room";
  const std::vector<Path> paths = toPosePaths(space, plan->paths);
  EXPECT_TRUE(visits(paths[1], {3, 1, 0})) << "b did not wait in the pocket at x = 3";
  Plan all;
  all.paths = {paths[0], paths[1], p.path};
  const ValidationResult v = validatePlan(w.map, w.instance, all);
  EXPECT_TRUE(v.valid()) << v.violation.message;
}

// Two robots driving east and two driving west along a corridor with two pockets: the orders
// of turns cost different expansions. fastestParkingPlan keeps the plan of the order that got
// everybody home in fewest (ties: the earlier), as the plans made alone in each order show, and
// gives the same plan and count with one thread or two.
// Four robots on a corridor with two pockets, planned in two orders.
World twoOrderWorld() {
  return World(mapFromRows({"................", "@@@.@@@@@@@@.@@@"}),
               {dot("a", {0, 0, 0}, {14, 0, 0}), dot("b", {6, 0, 0}, {15, 0, 0}),
                dot("c", {15, 0, 2}, {1, 0, 2}), dot("d", {10, 0, 2}, {5, 0, 2})});
}

long long sumOfCosts(const ParkingPlan& plan) {
  long long c = 0;
  for (const StatePath& p : plan.paths) c += static_cast<long long>(p.size()) - 1;
  return c;
}

// Each order's parking plan made alone, with its expansions.
struct OrdersAlone {
  std::vector<ParkingPlan> plans;
  std::vector<long long> expansions;
};

OrdersAlone planAlone(const SearchSpace& space, const std::vector<std::vector<int>>& orders) {
  OrdersAlone r;
  for (const std::vector<int>& order : orders) {
    long long e = 0;
    const auto plan = parkingPlan(space, order, Deadline::in(5.0), ParkingPlanOptions{}, e);
    EXPECT_TRUE(plan.has_value() && plan->robots_home == space.numAgents());
    if (!plan) return r;
    r.plans.push_back(*plan);
    r.expansions.push_back(e);
  }
  return r;
}

TEST(ParkingPlan, TheFastestOrderIsKeptWhateverTheThreads) {
  const World w = twoOrderWorld();
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  const std::vector<std::vector<int>> orders = {{0, 1, 2, 3}, {3, 2, 1, 0}};
  const OrdersAlone alone = planAlone(space, orders);
  ASSERT_EQ(alone.plans.size(), 2u);
  const std::vector<long long>& cost = alone.expansions;
  ASSERT_LT(cost[1], cost[0]) << "the world no longer tells the orders apart";
  ParkingPlanOptions options;
  options.order_slack = 1;
  for (int threads : {1, 2}) {
    long long expansions = 0;
    const auto plan = fastestParkingPlan(space, orders, Deadline::in(5.0), options, threads, expansions);
    ASSERT_TRUE(plan.has_value()) << threads << " threads";
    EXPECT_EQ(plan->order, 1) << threads << " threads";
    EXPECT_EQ(plan->paths, alone.plans[1].paths) << threads << " threads";
    EXPECT_EQ(expansions, 2 * cost[1]) << threads << " threads: the other order stops at the winner's count";
    const ValidationResult v = validateStatePaths(w, sub, space, plan->paths);
    EXPECT_TRUE(v.valid()) << violationName(v.violation.kind);
  }
}

TEST(ParkingPlan, TheCheapestOrderWithinTheSlackIsKeptWhateverTheThreads) {
  const World w = twoOrderWorld();
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  const std::vector<std::vector<int>> orders = {{2, 1, 0, 3}, {2, 3, 1, 0}};
  const OrdersAlone alone = planAlone(space, orders);
  ASSERT_EQ(alone.plans.size(), 2u);
  const std::vector<long long>& cost = alone.expansions;
  ASSERT_LT(cost[1], cost[0]);
  ASSERT_LT(sumOfCosts(alone.plans[0]), sumOfCosts(alone.plans[1]))
      << "the world no longer has the slower order make the cheaper plan";
  const double needed = static_cast<double>(cost[0]) / static_cast<double>(cost[1]);
  for (double slack : {needed * 1.01, needed * 0.99}) {
    ParkingPlanOptions options;
    options.order_slack = slack;
    const int kept = slack > needed ? 0 : 1;
    const long long limit = static_cast<long long>(slack * static_cast<double>(cost[1]));
    for (int threads : {1, 2}) {
      long long expansions = 0;
      const auto plan = fastestParkingPlan(space, orders, Deadline::in(5.0), options, threads, expansions);
      ASSERT_TRUE(plan.has_value()) << threads << " threads";
      EXPECT_EQ(plan->order, kept) << "slack " << slack << ", " << threads << " threads";
      EXPECT_EQ(plan->paths, alone.plans[kept].paths) << threads << " threads";
      EXPECT_EQ(expansions, cost[1] + std::min(cost[0], limit))
          << threads << " threads: the slower order stops at the slack's count";
      const ValidationResult v = validateStatePaths(w, sub, space, plan->paths);
      EXPECT_TRUE(v.valid()) << violationName(v.violation.kind);
    }
  }
}

TEST(ParkingPlan, WhereNoOrderGetsEverybodyHomeThePlanWithMostHomeIsKept) {
  const World w = twoOrderWorld();
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  const std::vector<std::vector<int>> orders = {{0, 1, 2, 3}, {3, 2, 1, 0}};
  // A budget at which neither order gets all four home and the second gets more home.
  ParkingPlanOptions options;
  std::vector<ParkingPlan> alone;
  bool found = false;
  for (long long budget = 1; budget < 100'000 && !found; budget += 1 + budget / 8) {
    options.max_expansions = budget;
    alone.clear();
    for (const std::vector<int>& order : orders) {
      long long e = 0;
      const auto plan = parkingPlan(space, order, Deadline::in(5.0), options, e);
      ASSERT_TRUE(plan.has_value());
      alone.push_back(*plan);
    }
    found = alone[1].robots_home > alone[0].robots_home && alone[1].robots_home < space.numAgents();
  }
  ASSERT_TRUE(found) << "the world no longer tells the orders apart under a budget";
  for (int threads : {1, 2}) {
    long long expansions = 0;
    const auto plan = fastestParkingPlan(space, orders, Deadline::in(5.0), options, threads, expansions);
    ASSERT_TRUE(plan.has_value()) << threads << " threads";
    EXPECT_EQ(plan->order, 1) << threads << " threads";
    EXPECT_EQ(plan->paths, alone[1].paths) << threads << " threads";
    EXPECT_EQ(plan->robots_home, alone[1].robots_home) << threads << " threads";
    EXPECT_FALSE(firstConflict(space, plan->paths).has_value()) << "a partial plan, but collision-free";
  }
}

TEST(ParkingPlan, IsLaLnsFirstPlanWithinItsBudgetOrItsBudgetPerRobot) {
  const World w = corridorWorld();
  Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  long long expansions = 0;
  const auto plan = planAll(space, expansions);
  ASSERT_TRUE(plan.has_value());
  // A budget that the plan fits in, and LA-LNS's soft first plan and repairs do not (about 700
  // expansions here).
  ASSERT_LT(expansions, 100);
  ASSERT_GT(expansions, 1);
  sub.max_expansions = 100;
  for (const bool per_robot : {false, true}) {
    LaLnsOptions options;
    options.parking_robots = 2;
    if (per_robot) {  // far too few for the plan alone, enough for two robots
      options.parking_expansions = 1;
      options.parking_expansions_per_robot = (expansions + 1) / 2;
    }
    LaLns lns(options);
    const Outcome solved = solveWith(lns, w, sub);
    ASSERT_TRUE(solvedValidly(solved)) << describe(solved);
    EXPECT_EQ(solved.result.paths, toPosePaths(space, plan->paths))
        << "every robot got home: its plan is the answer (per robot: " << per_robot << ")";
  }
}

}  // namespace
}  // namespace fleet_planner::test
