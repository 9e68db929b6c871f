// LA-LNS stuck on a swap that it can neither plan nor prove impossible: when it gives up, and
// what it does not search again meanwhile.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "fleet_planner/solvers/lns/la_lns.h"
#include "solver_test_util.h"
#include "test_maps.h"
#include "tiny_worlds.h"

namespace fleet_planner::test {
namespace {

// Two robots swapping ends of a one-row corridor, with both proofs out of reach (no joint
// states, no pair expansions): LA-LNS is stuck. When the caller has something else to try, it
// says so after a few repairs of every robot (for two robots, each the whole joint repair:
// knot_stall_repairs of them), long before its budget; otherwise it spends the budget.
TEST(LaLns, GivesUpWhenStuckOnlyIfTheCallerMayTrySomethingElse) {
  const World w = swapInARow(16);
  std::map<int, long long> given_up_after;  // expansions, by knot_stall_repairs
  for (const int knot_stall : {3, 6})
    for (const bool may_give_up : {true, false}) {
      SCOPED_TRACE(std::to_string(knot_stall) + (may_give_up ? " may give up" : ""));
      LaLnsOptions options;
      options.joint_search_nodes = 0;
      options.pair_proof_expansions = 0;
      options.knot_stall_repairs = knot_stall;
      LaLns solver(options);
      Subproblem sub = allRobots(w, 60.0);
      sub.max_expansions = 5'000'000;
      if (may_give_up) sub.may_give_up = [] { return true; };
      const Outcome o = solveWith(solver, w, sub);
      EXPECT_EQ(o.result.status, SolveStatus::Timeout) << describe(o);
      const std::string after =
          "stuck after " + std::to_string(knot_stall) + " repairs of every robot";
      const bool stuck = o.result.reason.find(after) != std::string::npos;
      EXPECT_EQ(stuck, may_give_up) << o.result.reason;
      EXPECT_EQ(o.result.reason.find("expansion budget") != std::string::npos, !may_give_up)
          << o.result.reason;
      if (may_give_up) {
        EXPECT_LT(o.result.stats.low_level_expansions, sub.max_expansions / 3) << describe(o);
        EXPECT_EQ(o.result.culprits, (std::vector<int>{0, 1}));
        given_up_after[knot_stall] = o.result.stats.low_level_expansions;
      }
    }
  EXPECT_LT(given_up_after[3], given_up_after[6]) << "fewer stalled repairs, sooner";
}

// That stuck swap with a joint search of 400 states, too few to decide it: every repair of
// the two is a joint repair, and with no path kept in between, each would run the same joint
// search again. It runs once: the expansions it adds are the same whether LA-LNS gives up
// after 3 or after 6 stalled repairs.
TEST(LaLns, DoesNotRepeatAJointSearchOnTheSamePaths) {
  const World w = swapInARow(16);
  std::map<int, long long> added;  // expansions of the joint searches, by knot_stall_repairs
  for (const int knot_stall : {3, 6}) {
    std::map<long long, long long> expansions;  // by joint_search_nodes
    for (const long long nodes : {0, 400}) {
      LaLnsOptions options;
      options.joint_search_nodes = nodes;
      options.pair_proof_expansions = 0;
      options.knot_stall_repairs = knot_stall;
      // Expansions, not the time share, bound each joint repair's LA-CBS, so that the counts
      // are the same on any machine (under the sanitizers 0.5 s ran out first).
      options.joint_seconds = 60;
      LaLns solver(options);
      Subproblem sub = allRobots(w, 60.0);
      sub.max_expansions = 5'000'000;
      sub.may_give_up = [] { return true; };
      const Outcome o = solveWith(solver, w, sub);
      ASSERT_EQ(o.result.status, SolveStatus::Timeout) << describe(o);
      ASSERT_NE(o.result.reason.find("stuck after"), std::string::npos) << o.result.reason;
      expansions[nodes] = o.result.stats.low_level_expansions;
    }
    added[knot_stall] = expansions[400] - expansions[0];
  }
  EXPECT_GT(added[3], 0);
  EXPECT_EQ(added[3], added[6]);
}

// The swap along a longer corridor that the pair proof decides when nobody else can help
// (LaLns.ProvesAnImpossibleSwapInALongCorridorByThePairAlone). When the caller may give up,
// robots of other subproblems stand among the static obstacles and could step aside: no pair
// proof is run, and LA-LNS gives up when stuck, as it would after a proof.
TEST(LaLns, LeavesPairProofsToTheCallerThatMayGiveUp) {
  const World w = swapInACorridorWithAPocket(16);
  for (const bool may_give_up : {false, true}) {
    SCOPED_TRACE(may_give_up ? "may give up" : "alone");
    LaLnsOptions options;
    options.joint_search_nodes = 500;
    LaLns solver(options);
    Subproblem sub = allRobots(w, 20.0);
    if (may_give_up) sub.may_give_up = [] { return true; };
    const Outcome o = solveWith(solver, w, sub);
    if (may_give_up) {
      EXPECT_EQ(o.result.status, SolveStatus::Timeout) << describe(o);
      EXPECT_NE(o.result.reason.find("stuck after"), std::string::npos) << o.result.reason;
    } else {
      EXPECT_EQ(o.result.status, SolveStatus::Infeasible) << describe(o);
    }
  }
}

// The stuck swap again, as the whole fleet of a caller that has another way to plan it
// (Subproblem::ends_when_stalled: the planner's coarser lattice): LA-LNS ends after
// end_stall_repairs repairs in a row without fewer colliding pairs, sooner for fewer, long
// before its budget; without the flag it spends the budget.
TEST(LaLns, EndsAfterStalledRepairsWhenTheCallerHasAnotherWay) {
  const World w = swapInARow(16);
  std::map<int, long long> ended_after;  // expansions, by end_stall_repairs
  for (const int stalled : {4, 8})
    for (const bool another_way : {true, false}) {
      SCOPED_TRACE(std::to_string(stalled) + (another_way ? " another way" : ""));
      LaLnsOptions options;
      options.joint_search_nodes = 0;
      options.pair_proof_expansions = 0;
      options.end_stall_repairs = stalled;
      LaLns solver(options);
      Subproblem sub = allRobots(w, 60.0);
      sub.max_expansions = 5'000'000;
      sub.ends_when_stalled = another_way;
      const Outcome o = solveWith(solver, w, sub);
      ASSERT_EQ(o.result.status, SolveStatus::Timeout) << describe(o);
      const std::string ended = "no fewer colliding pairs in " + std::to_string(stalled) + " repairs";
      EXPECT_EQ(o.result.reason.find(ended) != std::string::npos, another_way) << o.result.reason;
      if (another_way) {
        EXPECT_LT(o.result.stats.low_level_expansions, sub.max_expansions / 3) << describe(o);
        ended_after[stalled] = o.result.stats.low_level_expansions;
      }
    }
  EXPECT_LT(ended_after[4], ended_after[8]) << "fewer stalled repairs, sooner";
}

// Unlike may_give_up, ending when stalled keeps the pair proofs: the corridor swap that the
// pair proof decides is INFEASIBLE whether or not the caller has another way.
TEST(LaLns, KeepsPairProofsWhenItEndsOnAStall) {
  const World w = swapInACorridorWithAPocket(16);
  LaLnsOptions options;
  options.joint_search_nodes = 500;
  options.end_stall_repairs = 2;
  LaLns solver(options);
  Subproblem sub = allRobots(w, 20.0);
  sub.ends_when_stalled = true;
  const Outcome o = solveWith(solver, w, sub);
  EXPECT_EQ(o.result.status, SolveStatus::Infeasible) << describe(o);
}

}  // namespace
}  // namespace fleet_planner::test
