// LA-LNS's neighbourhood size: it doubles after a stall, stops at the subproblem's size, and
// falls back to its base on a new lowest number of colliding pairs.
#include "fleet_planner/solvers/lns/neighborhood_growth.h"

#include <gtest/gtest.h>

namespace fleet_planner {
namespace {

TEST(NeighborhoodGrowth, DoublesAfterAStallUpToEveryAgentAndFallsBackOnProgress) {
  NeighborhoodGrowth g(/*base=*/8, /*stall_repairs=*/3, /*agents=*/20);
  EXPECT_EQ(g.next(10), 8);  // first count: the lowest so far
  EXPECT_EQ(g.next(10), 8);
  EXPECT_EQ(g.next(11), 8);
  EXPECT_EQ(g.next(10), 16);  // three repairs without a new lowest count
  for (int k = 0; k < 2; ++k) EXPECT_EQ(g.next(10), 16);
  EXPECT_EQ(g.next(10), 20);  // every agent, not 32
  for (int k = 0; k < 3; ++k) EXPECT_EQ(g.next(10), 20);
  EXPECT_EQ(g.next(9), 8);  // progress
}

TEST(NeighborhoodGrowth, CountsStallsWithEveryAgentUntilProgress) {
  NeighborhoodGrowth g(/*base=*/2, /*stall_repairs=*/2, /*agents=*/3);
  EXPECT_EQ(g.next(5), 2);
  EXPECT_EQ(g.next(5), 2);
  EXPECT_EQ(g.next(5), 3);  // a stall at 2 agents grows the neighbourhood: not exhausted
  EXPECT_EQ(g.exhausted(), 0);
  EXPECT_EQ(g.next(5), 3);
  EXPECT_EQ(g.next(5), 3);  // a stall at every agent
  EXPECT_EQ(g.exhausted(), 1);
  EXPECT_EQ(g.next(5), 3);
  EXPECT_EQ(g.next(5), 3);
  EXPECT_EQ(g.exhausted(), 2);
  EXPECT_EQ(g.next(4), 2);  // progress
  EXPECT_EQ(g.exhausted(), 0);
}

TEST(NeighborhoodGrowth, CountsRepairsSinceTheLowestWhateverTheSize) {
  NeighborhoodGrowth g(/*base=*/2, /*stall_repairs=*/2, /*agents=*/8);
  EXPECT_EQ(g.next(5), 2);
  EXPECT_EQ(g.sinceBest(), 0);
  for (int k = 1; k <= 5; ++k) {
    g.next(5);
    EXPECT_EQ(g.sinceBest(), k) << "the size grows meanwhile";
  }
  g.next(4);
  EXPECT_EQ(g.sinceBest(), 0);  // progress
}

TEST(NeighborhoodGrowth, NeverMoreThanTheAgents) {
  NeighborhoodGrowth g(8, 1, 3);
  EXPECT_EQ(g.next(2), 3);
  EXPECT_EQ(g.next(2), 3);
}

}  // namespace
}  // namespace fleet_planner
