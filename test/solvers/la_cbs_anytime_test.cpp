// LA-CBS as an anytime search (`anytime`, la_cbs.h): stopped by a limit before it proves the
// optimum, it returns the cheapest conflict-free plan its primal step found, and its lower
// bound. Limits are node budgets, not times, so that every machine gives the same answers. Plans
// are checked by the independent plan validator; costs against the exhaustive optimum.
#include <gtest/gtest.h>

#include "exhaustive_search.h"
#include "fleet_planner/solvers/cbs/la_cbs.h"
#include "solver_test_util.h"
#include "test_maps.h"
#include "tiny_worlds.h"

namespace fleet_planner::test {
namespace {

Outcome solveWithin(const World& w, long long nodes, bool anytime) {
  LaCbsOptions options;
  options.max_high_level_nodes = nodes;
  options.anytime = anytime;
  LaCbs solver(options);
  return solveWith(solver, w, allRobots(w, 600.0));
}

// corridorToATarget (tiny_worlds.h): a must wait outside the corridor until b is through; the
// optimal tree pays for the wait split by split, the primal step plans it in one search.
TEST(LaCbsAnytime, ANodeLimitGivesTheBestPlanFoundAndABoundBelowTheOptimum) {
  const World w = corridorToATarget();
  const Outcome exact = solveWithin(w, -1, true);
  ASSERT_TRUE(solvedValidly(exact)) << describe(exact);
  ASSERT_EQ(exact.soc, 46);
  EXPECT_EQ(exact.result.stats.lower_bound, 46) << "an optimum proven is its own bound";
  const long long all = exact.result.stats.high_level_nodes;
  std::cout << "[ anytime   ] " << all << " nodes to the optimum\n";
  int unproven = 0;
  for (long long nodes = 1; nodes < all; nodes += std::max(1LL, all / 16)) {
    SCOPED_TRACE("nodes " + std::to_string(nodes));
    const Outcome cut = solveWithin(w, nodes, true);
    const Outcome before = solveWithin(w, nodes, false);
    EXPECT_EQ(before.result.status, SolveStatus::Timeout) << describe(before);
    EXPECT_LE(cut.result.stats.lower_bound, 46);
    EXPECT_EQ(cut.result.stats.lower_bound, before.result.stats.lower_bound) << "the same tree";
    if (cut.result.status != SolveStatus::Success) {
      EXPECT_EQ(cut.result.status, SolveStatus::Timeout) << describe(cut);
      continue;
    }
    ASSERT_TRUE(solvedValidly(cut)) << describe(cut);
    EXPECT_GE(cut.soc, 46);
    unproven += cut.result.stats.lower_bound < cut.soc;
  }
  EXPECT_GT(unproven, 0) << "no budget of the " << all << " nodes stopped with a plan in hand";
}

// On random tiny worlds with a tight budget: every plan returned passes the validator and costs
// at least the optimum, every bound is at most the optimum, and no plan where none exists.
TEST(LaCbsAnytime, PlansAndBoundsOnRandomTinyInstances) {
  Rng rng(41);
  int stopped_with_plan = 0, exact = 0;
  for (int round = 0; round < 100; ++round) {
    const std::unique_ptr<World> w = randomTinyWorld(rng, 3);
    const ExhaustiveResult best = exhaustiveSearch(w->map, w->instance, 4'000'000);
    if (best.budget_exhausted) continue;
    SCOPED_TRACE("round " + std::to_string(round));
    const Outcome o = solveWithin(*w, 20, true);
    const Outcome before = solveWithin(*w, 20, false);
    if (best.soc < 0) {
      EXPECT_NE(o.result.status, SolveStatus::Success) << describe(o);
      continue;
    }
    EXPECT_LE(o.result.stats.lower_bound, best.soc);
    if (!o.result.success()) continue;
    ASSERT_TRUE(solvedValidly(o)) << describe(o);
    EXPECT_GE(o.soc, best.soc);
    if (before.result.success()) {
      // The same optimum (the plan may be another: an incumbent that the tree's bound proves
      // optimal ends the search).
      EXPECT_EQ(o.soc, best.soc) << "a tree that ends on its own is optimal";
      ++exact;
    } else {
      ++stopped_with_plan;
    }
  }
  EXPECT_GT(stopped_with_plan, 0);
  EXPECT_GT(exact, 20);
  std::cout << "[ anytime   ] " << exact << " optimal, " << stopped_with_plan << " stopped with a plan\n";
}

}  // namespace
}  // namespace fleet_planner::test
