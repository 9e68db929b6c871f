// LA-CBS on scenarios that once made its constraint tree explode, and its pairwise delay
// heuristic. Every solved plan is checked with the independent plan validator.
#include <gtest/gtest.h>

#include <vector>

#include "fleet_planner/solvers/cbs/pairwise_delay.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

/// Two circular AMRs cross a 24 x 12 hall past a tug (a 4 x 2 block) that turns on the spot and
/// drives onto the AMRs' lane. The tug must wait while an AMR passes: with cell constraints
/// alone that is one split per step of waiting and the tree grew past 50,000 nodes without a
/// plan. Layered LA-CBS finds SOC 97; the optimum found by LA-CBS is 65.
TEST(LaCbsScenarios, ThreeRobotsWhereTugWaitsForPassingAmr) {
  const World w(mapFromRows({"@@@@@@@@@@@@@@@@@@@@@@@@", "@..............@.......@", "@......................@",
                             "@......................@", "@......................@", "@......................@",
                             "@......................@", "@......................@", "@.......@..............@",
                             "@.......@..............@", "@......................@", "@@@@@@@@@@@@@@@@@@@@@@@@"}),
                {makeRobot("amr_1", Footprint::circle(1.2), {3, 3, 0}, {19, 8, 0}),
                 makeRobot("amr_2", Footprint::circle(0.8), {19, 3, 1}, {3, 8, 1}),
                 makeRobot("tug", Footprint::block(-1.6, -0.8, 1.6, 0.8), {11, 6, 0}, {11, 3, 2})});
  const Outcome o = solveWith("la_cbs", w, allRobots(w, 300.0));
  ASSERT_TRUE(solvedValidly(o));
  EXPECT_LE(o.soc, 97) << describe(o);
}

TEST(PairwiseDelayBound, CoversTriangleExactly) {
  PairwiseDelayBound bound(3);
  bound.set(0, 1, 10 + 2);  // agents 0 and 1 need 2 more than their paths' costs 10 + 0
  bound.set(0, 2, 10 + 11);
  bound.set(1, 2, 0 + 8);
  // Extra costs x with x0 + x1 >= 2, x0 + x2 >= 11, x1 + x2 >= 8: at best 11, e.g. (3, 0, 8).
  EXPECT_EQ(bound.heuristic({10, 0, 0}), 11);
  bound.set(1, 2, 0 + 12);
  // x0 + x1 >= 2, x0 + x2 >= 11, x1 + x2 >= 12: at best 13, e.g. (0, 2, 11); a matching of
  // one pair would give only 12.
  EXPECT_EQ(bound.heuristic({10, 0, 0}), 13);
  EXPECT_EQ(bound.heuristic({20, 20, 20}), 0);
}

}  // namespace
}  // namespace fleet_planner::test
