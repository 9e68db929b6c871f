// The safeguard's steps before a merge (beyond the paper): the proof that two robots of a failed
// subproblem cannot both reach their targets, and the standing robots that step aside.
#include <gtest/gtest.h>

#include <algorithm>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/infeasibility/infeasible_pairs.h"
#include "fleet_planner/layered/plan_merge.h"
#include "fleet_planner/layered/step_aside.h"
#include "fleet_planner/layered/subproblem_solving.h"
#include "fleet_planner/layered/layered_planner.h"
#include "test_maps.h"
#include "test_robots.h"

namespace fleet_planner {
namespace {

using test::dot;
using test::footprintsOf;

// Two robots trading ends of a corridor: with a side pocket they can, without one they cannot.
Instance swapThrough(int length) {
  Instance in;
  in.robots = {dot("A", {0, 0, 0}, {length - 1, 0, 0}), dot("B", {length - 1, 0, 1}, {0, 0, 1})};
  return in;
}

TEST(InfeasiblePairs, CorridorSwapWithoutPocketIsProvenAndNamesBothRobots) {
  const GridMap map = test::mapFromRows({"......."});
  const Instance in = swapThrough(7);
  const FleetGraphs graphs(map, footprintsOf(in));
  const std::optional<std::string> proof = findInfeasiblePair(in, graphs, {{0, 1}}, 1'000'000, Deadline::in(5.0));
  ASSERT_TRUE(proof.has_value());
  EXPECT_NE(proof->find("'A' and 'B'"), std::string::npos) << *proof;
}

TEST(InfeasiblePairs, CorridorSwapWithPocketIsNotProven) {
  const GridMap map = test::mapFromRows({".......", "@@@.@@@"});
  const Instance in = swapThrough(7);
  const FleetGraphs graphs(map, footprintsOf(in));
  EXPECT_FALSE(findInfeasiblePair(in, graphs, {{0, 1}}, 1'000'000, Deadline::in(5.0)).has_value());
}

TEST(InfeasiblePairs, AnExpiredDeadlineProvesNothing) {
  const GridMap map = test::mapFromRows({"......."});
  const Instance in = swapThrough(7);
  const FleetGraphs graphs(map, footprintsOf(in));
  EXPECT_FALSE(findInfeasiblePair(in, graphs, {{0, 1}}, 1'000'000, Deadline::in(0.0)).has_value());
}

// B must pass the cell where A ends, A waits in a side cell: A first leaves B no way, B first
// serves. The pair is planned in turn, B first, and the plan is valid.
TEST(InfeasiblePairs, APairIsPlannedInTurnInTheOrderThatServes) {
  const GridMap map = test::mapFromRows({".....", "@.@@@"});
  Instance in;
  in.robots = {dot("A", {1, 1, 3}, {2, 0, 0}), dot("B", {0, 0, 0}, {4, 0, 0})};
  const FleetGraphs graphs(map, footprintsOf(in));
  Subproblem alone;
  alone.instance = &in;
  alone.graphs = &graphs;
  const SolveResult r = planPairInTurn(alone, 0, 1, 10'000, Deadline::in(5.0));
  ASSERT_TRUE(r.success()) << r.reason;
  EXPECT_TRUE(validatePlan(map, in, Plan{r.paths}).valid());
  EXPECT_GT(r.paths[0].size(), 3u);  // A waits for B
}

// Trading ends of a corridor through a side pocket takes both robots' manoeuvre: no order
// serves, and planning in turn decides nothing (the pair proof then goes on to LA-LaCAM).
TEST(InfeasiblePairs, ASwapThroughAPocketIsNotPlannedInTurn) {
  const GridMap map = test::mapFromRows({".......", "@@@.@@@"});
  const Instance in = swapThrough(7);
  const FleetGraphs graphs(map, footprintsOf(in));
  Subproblem alone;
  alone.instance = &in;
  alone.graphs = &graphs;
  EXPECT_EQ(planPairInTurn(alone, 0, 1, 10'000, Deadline::in(5.0)).status, SolveStatus::Timeout);
}

// The layered planner answers INFEASIBLE, naming the pair, instead of merging and timing out:
// each robot alone passes the pre-check, but A and B are entangled (no order of the two serves)
// and the pair proof ends it before any subproblem is solved.
Instance swapBesideALane() {
  Instance in = swapThrough(7);
  in.robots.push_back(dot("C", {0, 2, 0}, {6, 2, 0}));
  return in;
}

TEST(InfeasiblePairs, LayeredPlannerReportsTheProvenPairBeforeSolving) {
  const GridMap map = test::mapFromRows({".......", "@@@@@@@", "......."});
  const Instance in = swapBesideALane();
  const FleetGraphs graphs(map, footprintsOf(in));
  for (const char* backend : {"la_cbs", "la_lacam", "la_lns"}) {
    LayeredOptions o;
    o.backend = backend;
    const LayeredResult r = planLayered(map, in, graphs, o, Deadline::in(2.0));
    EXPECT_EQ(r.status, SolveStatus::Infeasible) << backend << ": " << r.reason;
    EXPECT_NE(r.reason.find("'A' and 'B' cannot both reach"), std::string::npos) << backend << ": " << r.reason;
    EXPECT_NE(r.reason.find("found before solving"), std::string::npos)
        << backend << ": " << r.reason;
    for (const SolvedSubproblem& s : r.subproblems) EXPECT_EQ(s.attempts, 0) << backend;
  }
}

// Without the entangled pairs (a decomposition cut short), the pairs of the subproblem that
// failed are tried instead.
TEST(InfeasiblePairs, WithoutEntangledPairsAFailedSubproblemsPairsAreTried) {
  const GridMap map = test::mapFromRows({".......", "@@@@@@@", "......."});
  const Instance in = swapBesideALane();
  const FleetGraphs graphs(map, footprintsOf(in));
  std::vector<SolvedSubproblem> order(2);
  order[0].robots = {0, 1};
  order[1].robots = {2};
  order[1].cluster = 1;
  SubproblemSolvingOptions o;
  o.backend = "la_lns";
  const SubproblemSolving solved = solveSubproblems(in, graphs, order, o, Deadline::in(4.0));
  EXPECT_EQ(solved.status, SolveStatus::Infeasible) << solved.reason;
  EXPECT_NE(solved.reason.find("'A' and 'B' cannot both reach"), std::string::npos)
      << solved.reason;
  EXPECT_NE(solved.reason.find("found after subproblem 0"), std::string::npos) << solved.reason;
}

// An entangled pair that can pass each other (here through a side pocket) is no proof: the
// planner solves the instance.
TEST(InfeasiblePairs, AnEntangledPairThatCanPassIsSolved) {
  const GridMap map = test::mapFromRows({".......", "@@@.@@@", "......."});
  const Instance in = swapBesideALane();
  const FleetGraphs graphs(map, footprintsOf(in));
  LayeredOptions o;
  o.backend = "la_lacam";
  const LayeredResult r = planLayered(map, in, graphs, o, Deadline::in(10.0));
  ASSERT_EQ(r.status, SolveStatus::Success) << r.reason;
  const std::vector<std::pair<int, int>> entangled{{0, 1}};
  EXPECT_EQ(r.decomposition.entangled_pairs, entangled);
  EXPECT_TRUE(validatePlan(map, in, r.plan).valid());
}

TEST(StepAside, PicksStandingRobotsNearTheWayOnly) {
  // A's shortest path runs along row 0; one robot stands beside it, one far below.
  const GridMap map = test::freeMap(12, 12);
  Instance in;
  in.robots = {dot("A", {0, 0, 0}, {11, 0, 0}), dot("near", {5, 2, 0}, {5, 2, 0}), dot("far", {5, 11, 0}, {5, 11, 0})};
  const FleetGraphs graphs(map, footprintsOf(in));
  const std::vector<StaticFootprint> standing{{1, {5, 2, 0}}, {2, {5, 11, 0}}};
  const std::vector<StaticFootprint> near = robotsInTheWay(in, graphs, {0}, standing, 2, 8);
  ASSERT_EQ(near.size(), 1u);
  EXPECT_EQ(near[0].robot, 1);
}

TEST(StepAside, KeepsTheNearestWhenCapped) {
  const GridMap map = test::freeMap(12, 12);
  Instance in;
  in.robots = {dot("A", {0, 0, 0}, {11, 0, 0}), dot("beside", {5, 3, 0}, {5, 3, 0}), dot("on", {8, 1, 0}, {8, 1, 0})};
  const FleetGraphs graphs(map, footprintsOf(in));
  const std::vector<StaticFootprint> standing{{1, {5, 3, 0}}, {2, {8, 1, 0}}};
  EXPECT_EQ(robotsInTheWay(in, graphs, {0}, standing, 2, 8).size(), 2u);
  const std::vector<StaticFootprint> one = robotsInTheWay(in, graphs, {0}, standing, 2, 1);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].robot, 2);
}

TEST(StepAside, PicksTheStandingRobotsAPlanDrivesThrough) {
  // A drives down column 0 and then east along row 11: it passes "on" (row 11), brushes nobody
  // else; "beside" stands next to its way without touching it.
  const GridMap map = test::freeMap(12, 12);
  Instance in;
  in.robots = {dot("A", {0, 0, 2}, {11, 11, 0}), dot("on", {6, 11, 0}, {6, 11, 0}),
               dot("beside", {1, 5, 0}, {1, 5, 0})};
  const FleetGraphs graphs(map, footprintsOf(in));
  Path way;
  for (int y = 0; y <= 11; ++y) way.push_back({0, y, 2});
  way.push_back({0, 11, 0});
  for (int x = 1; x <= 11; ++x) way.push_back({x, 11, 0});
  const std::vector<StaticFootprint> standing{{1, {6, 11, 0}}, {2, {1, 5, 0}}};
  const std::vector<StaticFootprint> on = robotsOnPaths(graphs, {0}, {way}, standing);
  ASSERT_EQ(on.size(), 1u);
  EXPECT_EQ(on[0].robot, 1);
  EXPECT_TRUE(robotsOnPaths(graphs, {0}, {Path{{0, 0, 2}}}, standing).empty());
}

TEST(PlanMerge, ARobotWithAPathContinuesItAfterItsEnd) {
  // h drove to (3, 0) earlier; now it steps into the pocket and back. Its new part starts once
  // its earlier path has ended, and its own earlier path does not delay it further.
  const GridMap map = test::mapFromRows({".......", "@@@.@@@"});
  Instance in;
  in.robots = {dot("h", {0, 0, 0}, {3, 0, 0}), dot("o", {6, 0, 1}, {6, 0, 1})};
  const FleetGraphs graphs(map, footprintsOf(in));
  std::vector<Path> merged{{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}, {{6, 0, 1}}};
  const std::vector<char> done{1, 1};
  std::vector<Path> fresh{{{3, 0, 0}, {3, 0, 2}, {3, 1, 2}, {3, 1, 0}, {3, 1, 3}, {3, 0, 3}, {3, 0, 0}}};
  EXPECT_EQ(delayToFit(graphs, merged, done, {0}, fresh), 3);
  appendDelayed(merged, 0, fresh[0]);
  const Path expected{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {3, 0, 2},
                      {3, 1, 2}, {3, 1, 0}, {3, 1, 3}, {3, 0, 3}, {3, 0, 0}};
  EXPECT_EQ(merged[0], expected);
  Plan plan;
  plan.paths = merged;
  const ValidationResult v = validatePlan(map, in, plan);
  EXPECT_TRUE(v.valid()) << v.violation.message;
}

}  // namespace
}  // namespace fleet_planner
