// The backward search of a pair's goal (pair_goal_search.h): it must agree with a complete
// forward search (LA-LaCAM) wherever both finish, and it proves pairs that LA-LaCAM cannot.
#include "fleet_planner/infeasibility/pair_goal_search.h"

#include <gtest/gtest.h>

#include <iostream>
#include <optional>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/io/instance_generator.h"
#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/infeasibility/infeasible_pairs.h"
#include "fleet_planner/solvers/lacam/la_lacam.h"
#include "random_worlds.h"
#include "test_robots.h"

namespace fleet_planner {
namespace {

using test::dot;
using test::footprintsOf;

PairReach backwards(const Instance& in, const FleetGraphs& graphs, long long budget = 1'000'000) {
  return searchPairBackwards(graphs, {0, in.robots[0].start, in.robots[0].target},
                             {1, in.robots[1].start, in.robots[1].target}, budget,
                             Deadline::in(20.0))
      .reach;
}

Instance corridorSwap() {
  Instance in;
  in.robots = {dot("A", {0, 0, 0}, {6, 0, 0}), dot("B", {6, 0, 1}, {0, 0, 1})};
  return in;
}

TEST(PairGoalSearch, CorridorSwapWithoutPocketIsUnreachable) {
  const GridMap map = test::mapFromRows({"......."});
  const Instance in = corridorSwap();
  EXPECT_EQ(backwards(in, FleetGraphs(map, footprintsOf(in))), PairReach::Unreachable);
}

TEST(PairGoalSearch, CorridorSwapWithPocketIsReachable) {
  const GridMap map = test::mapFromRows({".......", "@@@.@@@"});
  const Instance in = corridorSwap();
  EXPECT_EQ(backwards(in, FleetGraphs(map, footprintsOf(in))), PairReach::Reachable);
}

TEST(PairGoalSearch, ABudgetTooSmallDecidesNothing) {
  const GridMap map = test::mapFromRows({".......", "@@@.@@@"});
  const Instance in = corridorSwap();
  EXPECT_EQ(backwards(in, FleetGraphs(map, footprintsOf(in)), 3), PairReach::Unknown);
}

// LA-LaCAM with no expansions decides nothing; the pair proof then searches backwards.
TEST(PairGoalSearch, ThePairProofFallsBackToIt) {
  const GridMap map = test::mapFromRows({"......."});
  const Instance in = corridorSwap();
  const FleetGraphs graphs(map, footprintsOf(in));
  const std::optional<std::string> proof =
      findInfeasiblePair(in, graphs, {{0, 1}}, 0, Deadline::in(5.0));
  ASSERT_TRUE(proof.has_value());
  EXPECT_NE(proof->find("every configuration from which both can reach their targets"),
            std::string::npos)
      << *proof;
}

// A pair with few configurations that reach its targets is decided by a short backward search
// first, whatever the forward search's budget (which it would spend on a larger map before
// failing).
TEST(PairGoalSearch, ThePairProofTriesItFirst) {
  const GridMap map = test::mapFromRows({"......."});
  const Instance in = corridorSwap();
  const FleetGraphs graphs(map, footprintsOf(in));
  const std::optional<std::string> proof =
      findInfeasiblePair(in, graphs, {{0, 1}}, 1'000'000, Deadline::in(5.0));
  ASSERT_TRUE(proof.has_value());
  EXPECT_NE(proof->find("every configuration from which both can reach their targets"),
            std::string::npos)
      << *proof;
  // With a pocket the pair can trade places: no proof.
  const GridMap pocket = test::mapFromRows({".......", "@@@.@@@"});
  EXPECT_FALSE(findInfeasiblePair(in, FleetGraphs(pocket, footprintsOf(in)), {{0, 1}}, 1'000'000, Deadline::in(5.0)));
}

// Random pairs of robots up to 3 x 3 cells on small maps with obstacles, where LA-LaCAM's
// search is complete within its budget: both searches give the same answer, and LA-LaCAM's plan
// for a reachable pair is valid.
TEST(PairGoalSearch, AgreesWithACompleteForwardSearch) {
  int reachable = 0, unreachable = 0, undecided = 0;
  for (std::uint64_t seed = 0; seed < 1000; ++seed) {
    const GridMap map = test::randomMap(seed, 5, 3, 4, 4);
    GeneratorOptions g;
    g.robots = 2;
    g.seed = seed;
    g.max_size = 1.5;
    std::optional<Instance> in;
    try {
      in = generateInstance(map, g);
    } catch (const InvalidInput&) {
      continue;
    }
    const FleetGraphs graphs(map, footprintsOf(*in));
    Subproblem pair;
    pair.instance = &*in;
    pair.graphs = &graphs;
    pair.robots = {0, 1};
    pair.deadline = Deadline::in(20.0);
    pair.max_expansions = 2'000'000;
    const SolveResult forward = LaLacam().solve(pair);
    if (!forward.success() && forward.status != SolveStatus::Infeasible) {
      ++undecided;
      continue;
    }
    const PairReach back = backwards(*in, graphs);
    ASSERT_NE(back, PairReach::Unknown) << "seed " << seed;
    EXPECT_EQ(back == PairReach::Reachable, forward.success())
        << "seed " << seed << ": " << forward.reason;
    if (forward.success())
      EXPECT_TRUE(validatePlan(map, *in, Plan{forward.paths}).valid()) << "seed " << seed;
    (forward.success() ? reachable : unreachable) += 1;
  }
  EXPECT_GT(reachable, 150);
  EXPECT_GT(unreachable, 30);
  std::cout << "[ pairs     ] " << reachable << " reachable, " << unreachable << " unreachable, "
            << undecided << " undecided by LA-LaCAM\n";
}

}  // namespace
}  // namespace fleet_planner
