// Two agents trading places through a pocket (pocket_repair.h): in a corridor with one side
// pocket, where the ordered repair fails in both orders, the parking agent waits in the pocket
// and both paths pass the plan validator; without the pocket there is no repair. Where every
// state of the parking agent covers the other's way, it waits beside the way where the
// corridor widens (options.beside_way).
#include <gtest/gtest.h>

#include <algorithm>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/solvers/lns/ordered_repair.h"
#include "fleet_planner/solvers/lns/pocket_repair.h"
#include "fleet_planner/solvers/search/solve_common.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

// "t" stands at the corridor's west end for good (in the table); "a" drives the corridor east
// through "b"'s start, "b" drives it west through "a"'s start.
World swapWorld(bool pocket) {
  return World(mapFromRows({"..............", pocket ? "@@@@@@.@@@@@@@" : "@@@@@@@@@@@@@@",
                            pocket ? "@@@@@@.@@@@@@@" : "@@@@@@@@@@@@@@"}),
               {dot("t", {0, 0, 0}, {0, 0, 0}), dot("a", {1, 0, 0}, {12, 0, 0}),
                dot("b", {10, 0, 2}, {2, 0, 2})});
}

StatePath shortestPath(const SearchSpace& space, int a) {
  const LowLevelResult r = spaceTimeAStar(space, a, AgentConstraints{}, Deadline::in(5.0));
  return r.outcome == LowLevelResult::Outcome::Found ? r.path : StatePath{};
}

TEST(PocketRepair, TheParkingAgentWaitsInThePocketAndNobodyCollides) {
  const World w = swapWorld(/*pocket=*/true);
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  SoftPathTable table(space);
  const StatePath runner = shortestPath(space, 0);
  ASSERT_FALSE(runner.empty());
  table.insert(0, runner);
  long long expansions = 0;
  for (const std::vector<int>& order : {std::vector<int>{1, 2}, std::vector<int>{2, 1}}) {
    EXPECT_FALSE(orderedRepair(space, table, order, Deadline::in(5.0), 100'000, expansions))
        << "each start is on the other's way: no order works";
  }
  for (const auto& [through, parks] : {std::pair{1, 2}, std::pair{2, 1}}) {
    expansions = 0;
    const auto paths = pocketRepair(space, table, through, {parks}, shortestPath(space, through),
                                    Deadline::in(5.0), PocketRepairOptions{}, expansions);
    ASSERT_TRUE(paths.has_value()) << space.label(parks) << " parking";
    EXPECT_GT(expansions, 0);
    EXPECT_FALSE(table.contains(1) || table.contains(2)) << "the table is left as it was";
    ASSERT_TRUE(table.contains(0));
    std::vector<StatePath> all{runner, {}, {}};
    all[through] = (*paths)[0];
    all[parks] = (*paths)[1];
    Plan plan;
    plan.paths = toPosePaths(space, all);
    const ValidationResult v = validatePlan(w.map, w.instance, plan);
    EXPECT_TRUE(v.valid()) << violationName(v.violation.kind) << " with " << space.label(parks)
                           << " parking";
    const Path& parked = plan.paths[parks];
    EXPECT_TRUE(std::any_of(parked.begin(), parked.end(), [](const GridPose& p) { return p.y > 0; }))
        << space.label(parks) << " never enters the pocket";
    const auto again = pocketRepair(space, table, through, {parks}, shortestPath(space, through),
                                    Deadline::in(5.0), PocketRepairOptions{}, expansions);
    ASSERT_TRUE(again.has_value());
    EXPECT_EQ(*again, *paths) << "same input, same paths";
  }
}

TEST(PocketRepair, NoPocketNoRepair) {
  const World w = swapWorld(/*pocket=*/false);
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  SoftPathTable table(space);
  long long expansions = 0;
  for (const auto& [through, parks] : {std::pair{1, 2}, std::pair{2, 1}}) {
    EXPECT_FALSE(pocketRepair(space, table, through, {parks}, shortestPath(space, through),
                              Deadline::in(5.0), PocketRepairOptions{}, expansions));
  }
  EXPECT_FALSE(table.contains(1) || table.contains(2));
}

// A corridor three cells high with a fourth row at x = 4..10. "p", a block two cells wide and
// three high facing west, cannot turn anywhere (its turn sweeps five rows), so it covers row 1,
// the dot "t"'s way east, wherever it stands; "t" can pass it only by the fourth row.
World besideWorld() {
  return World(mapFromRows({"................", "................", "................", "@@@@.......@@@@@"}),
               {dot("t", {0, 1, 0}, {15, 1, 0}),
                makeRobot("p", Footprint::block(-0.4, -1.4, 1.4, 1.4), {12, 1, 1}, {2, 1, 1})});
}

TEST(PocketRepair, BesideTheWayWhereTheCorridorWidens) {
  const World w = besideWorld();
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  SoftPathTable table(space);
  const StatePath way = shortestPath(space, 0);
  ASSERT_FALSE(way.empty());
  long long expansions = 0;
  for (const std::vector<int>& order : {std::vector<int>{0, 1}, std::vector<int>{1, 0}}) {
    EXPECT_FALSE(orderedRepair(space, table, order, Deadline::in(5.0), 100'000, expansions));
  }
  std::vector<char> marks;
  markWay(space, 0, way, marks);
  EXPECT_TRUE(pocketsOffWay(space, 1, table, marks, PocketRepairOptions{}).empty())
      << "every state of p covers t's way";
  EXPECT_FALSE(pocketRepair(space, table, 0, {1}, way, Deadline::in(5.0), PocketRepairOptions{}, expansions));

  const StateGraph& g = space.graph(1);
  EXPECT_FALSE(passesBeside(space, 0, way, 1, g.id({12, 1, 1}), 100'000, expansions)) << "at its start";
  EXPECT_TRUE(passesBeside(space, 0, way, 1, g.id({8, 1, 1}), 100'000, expansions)) << "by the fourth row";
  EXPECT_FALSE(passesBeside(space, 0, way, 1, g.id({8, 1, 1}), 5, expansions)) << "not within 5 expansions";

  PocketRepairOptions beside;
  beside.beside_way = true;
  const auto paths = pocketRepair(space, table, 0, {1}, way, Deadline::in(5.0), beside, expansions);
  ASSERT_TRUE(paths.has_value());
  EXPECT_FALSE(table.contains(0) || table.contains(1)) << "the table is left as it was";
  Plan plan;
  plan.paths = toPosePaths(space, *paths);
  const ValidationResult v = validatePlan(w.map, w.instance, plan);
  EXPECT_TRUE(v.valid()) << violationName(v.violation.kind);
  EXPECT_TRUE(std::any_of(plan.paths[0].begin(), plan.paths[0].end(), [](const GridPose& p) { return p.y == 3; }))
      << "t passes by the fourth row";
  const auto again = pocketRepair(space, table, 0, {1}, way, Deadline::in(5.0), beside, expansions);
  ASSERT_TRUE(again.has_value());
  EXPECT_EQ(*again, *paths) << "same input, same paths";
}

// Robots 95 and 293 of `generate --seed 1` with 300 robots on Paris_1_256 (the paper's
// benchmark, read from ../shared when it is there). 95, a block 3.2 x 4 cells against the map's
// top edge, starts on 293's way to its target and cannot leave the strip that way runs along;
// 293 passes it only where the strip widens, turning some steps before it. LA-LNS (raw) found
// no plan before the parker could wait beside the way.
TEST(PocketRepair, LaLnsLetsABlockWaitBesideAWayOnTheEdgeOfParis) {
  const std::optional<GridMap> paris = sharedBenchmarkMap("Paris_1_256");
  if (!paris) GTEST_SKIP() << "no ../shared/benchmark";
  const World w(*paris,
                {makeRobot("95", Footprint::block(-1.9, -2, 1.3, 2), {231, 2, 0}, {226, 2, 1}),
                 makeRobot("293", Footprint::block(-1.3, -1.4, 1.3, 1.4), {220, 92, 3}, {245, 5, 0})});
  Subproblem sub = allRobots(w, 120.0);
  sub.max_expansions = 6'000'000;
  const Outcome o = solveWith("la_lns", w, sub);
  ASSERT_TRUE(solvedValidly(o)) << describe(o);
}

}  // namespace
}  // namespace fleet_planner::test
