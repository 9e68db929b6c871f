// LA-CBS with `suboptimality` above 1 (ECBS: focal searches at both levels, la_cbs.h): plans
// validated by the independent plan validator, their cost within the weight of the exhaustive
// optimum, no plan where none exists, and fewer constraint-tree nodes where the optimal tree
// pays for every step of a wait.
#include <gtest/gtest.h>

#include "exhaustive_search.h"
#include "fleet_planner/solvers/cbs/la_cbs.h"
#include "fleet_planner/solvers/registry.h"
#include "solver_test_util.h"
#include "test_maps.h"
#include "tiny_worlds.h"

namespace fleet_planner::test {
namespace {

Outcome solveFocal(const World& w, double weight, double seconds = 20.0) {
  auto solver = makeSolver("la_cbs", {{"la_cbs", {{"suboptimality", weight}}}});
  return solveWith(*solver, w, allRobots(w, seconds));
}

TEST(LaCbsFocal, WithinTheWeightOfTheOptimumOnRandomTinyInstances) {
  Rng rng(29);
  int solved = 0, proven = 0, above = 0;
  for (int round = 0; round < 100; ++round) {
    const std::unique_ptr<World> w = randomTinyWorld(rng, round % 3 == 0 ? 3 : 2);
    const ExhaustiveResult best = exhaustiveSearch(w->map, w->instance, 4'000'000);
    if (best.budget_exhausted) continue;
    SCOPED_TRACE("round " + std::to_string(round));
    LaCbsOptions options;
    options.suboptimality = 1.5;
    options.max_high_level_nodes = 200'000;  // a budget, not a time: the same on every machine
    LaCbs solver(options);
    const Outcome o = solveWith(solver, *w, allRobots(*w, 600.0));
    if (best.soc < 0) {
      EXPECT_NE(o.result.status, SolveStatus::Success) << describe(o);
      ++proven;
      continue;
    }
    ASSERT_TRUE(solvedValidly(o)) << describe(o);
    EXPECT_LE(o.soc, 1.5 * best.soc);
    EXPECT_GE(o.soc, best.soc);
    above += o.soc > best.soc;
    ++solved;
  }
  EXPECT_GT(solved, 40);
  EXPECT_GT(proven, 15);
  std::cout << "[ focal     ] " << solved << " solved (" << above << " above the optimum), " << proven
            << " without a plan\n";
}

// With a weight just above 1 (and costs below 100) the answer is optimal: neither the focal
// searches nor a plan made by planning one robot around the others' paths may cost more.
TEST(LaCbsFocal, AWeightNearOneKeepsTheOptimum) {
  Rng rng(31);
  int solved = 0;
  for (int round = 0; round < 60; ++round) {
    const std::unique_ptr<World> w = randomTinyWorld(rng, round % 3 == 0 ? 3 : 2);
    const ExhaustiveResult best = exhaustiveSearch(w->map, w->instance, 4'000'000);
    if (best.budget_exhausted || best.soc < 0 || best.soc >= 100) continue;
    LaCbsOptions options;
    options.suboptimality = 1.0 + 1.0 / 128;
    options.max_high_level_nodes = 200'000;
    LaCbs solver(options);
    const Outcome o = solveWith(solver, *w, allRobots(*w, 600.0));
    SCOPED_TRACE("round " + std::to_string(round));
    ASSERT_TRUE(solvedValidly(o)) << describe(o);
    EXPECT_EQ(o.soc, best.soc);
    ++solved;
  }
  EXPECT_GT(solved, 20);
}

// corridorToATarget (tiny_worlds.h): a must wait outside the corridor until b is through.
TEST(LaCbsFocal, FewerTreeNodesWhereARobotMustWaitForACorridor) {
  const World w = corridorToATarget();
  LaCbs optimal;
  const Outcome exact = solveWith(optimal, w, allRobots(w, 300.0));
  ASSERT_TRUE(solvedValidly(exact)) << describe(exact);
  EXPECT_EQ(exact.soc, 46);
  const Outcome focal = solveFocal(w, 1.2, 300.0);
  ASSERT_TRUE(solvedValidly(focal)) << describe(focal);
  EXPECT_LE(focal.soc, 1.2 * 46);
  EXPECT_LT(focal.result.stats.high_level_nodes, exact.result.stats.high_level_nodes)
      << focal.result.stats.high_level_nodes << " against " << exact.result.stats.high_level_nodes;
}

TEST(LaCbsFocal, SameInputSamePlan) {
  const World w = corridorToATarget();
  const Outcome a = solveFocal(w, 1.2), b = solveFocal(w, 1.2);
  ASSERT_TRUE(solvedValidly(a)) << describe(a);
  ASSERT_TRUE(solvedValidly(b)) << describe(b);
  EXPECT_EQ(a.plan.paths, b.plan.paths);
  EXPECT_EQ(a.result.stats.high_level_nodes, b.result.stats.high_level_nodes);
}

TEST(LaCbsFocal, TheWeightIsCheckedByName) {
  EXPECT_THROW(makeSolver("la_cbs", {{"la_cbs", {{"suboptimality", 0.9}}}}), InvalidInput);
}

}  // namespace
}  // namespace fleet_planner::test
