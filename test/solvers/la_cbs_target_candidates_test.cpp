// LA-CBS's target candidates (la_cbs.h, cbs_split.h): the earliest conflict of a pair at which
// one robot already holds its target, split on that robot's cost even when the pair met earlier
// on the way. Every solved plan is checked with the independent plan validator.
#include <gtest/gtest.h>

#include <vector>

#include "exhaustive_search.h"
#include "fleet_planner/solvers/cbs/cbs_split.h"
#include "fleet_planner/solvers/cbs/la_cbs.h"
#include "fleet_planner/solvers/registry.h"
#include "solver_test_util.h"
#include "test_maps.h"
#include "tiny_worlds.h"

namespace fleet_planner::test {
namespace {

StatePath statesOf(const SearchSpace& space, int a, const std::vector<GridPose>& poses) {
  StatePath path;
  for (const GridPose& p : poses) path.push_back(space.graph(a).id(p));
  return path;
}

// a drives to its target (5, 2) and parks there from t = 3; b crosses a's way at t = 1, then
// drives over a's target at t = 4. The pair's earliest conflict (t = 1) is no target conflict;
// the one at t = 4 is, with a as the robot that holds its target.
TEST(TargetConflicts, FindsTheParkedRobotsConflictAfterAnEarlierOne) {
  const World w(freeMap(10, 5), {dot("a", {2, 2, 0}, {5, 2, 0}), dot("b", {3, 1, 2}, {7, 2, 0})});
  const SearchSpace space(allRobots(w));
  const std::vector<StatePath> paths = {
      statesOf(space, 0, {{2, 2, 0}, {3, 2, 0}, {4, 2, 0}, {5, 2, 0}}),
      statesOf(space, 1, {{3, 1, 2}, {3, 2, 2}, {3, 2, 0}, {4, 2, 0}, {5, 2, 0}, {6, 2, 0}, {7, 2, 0}})};
  const std::vector<AgentConflict> earliest = earliestConflictPerPair(space, paths, 4);
  ASSERT_EQ(earliest.size(), 1u);
  EXPECT_EQ(earliest[0].t, 1);
  EXPECT_FALSE(holdsTargetAt(space, paths[0], 0, 1));
  EXPECT_TRUE(holdsTargetAt(space, paths[0], 0, 3));
  EXPECT_FALSE(holdsTargetAt(space, paths[1], 1, 4));

  const std::vector<AgentConflict> target = targetConflicts(space, paths);
  ASSERT_EQ(target.size(), 1u);
  EXPECT_EQ(target[0].a, 0);
  EXPECT_EQ(target[0].b, 1);
  EXPECT_EQ(target[0].t, 4);
  EXPECT_EQ(target[0].kind, AgentConflict::Kind::Vertex);
  EXPECT_EQ(target[0].cell.x, 5);
  EXPECT_EQ(target[0].cell.y, 2);
  // Its split: a's cost above 4, or at most 4 with b kept off a's target from 4 on.
  const auto branches = splitConflict(space, paths, target[0]);
  EXPECT_EQ(branches[0].replan, 0);
  ASSERT_EQ(branches[0].constraints.size(), 1u);
  EXPECT_EQ(branches[0].constraints[0].kind, CbsConstraint::Kind::CostAbove);
  EXPECT_EQ(branches[1].replan, 1);
  ASSERT_EQ(branches[1].constraints.size(), 2u);
  EXPECT_EQ(branches[1].constraints[1].kind, CbsConstraint::Kind::TargetAreaFrom);
  EXPECT_EQ(branches[1].constraints[1].t, 4);
}

Outcome solveCbs(const World& w, bool target_candidates) {
  LaCbsOptions options;
  options.target_candidates = target_candidates;
  LaCbs solver(options);
  return solveWith(solver, w, allRobots(w, 300.0));
}

// corridorToATarget (tiny_worlds.h): the optimum (46, by exhaustive search) has a wait until b
// is through. With cell splits alone the pair meets head-on in the corridor step after step and
// the tree took 1,650 nodes; split on a's cost at the conflict where b drives over a's parked
// target, 448.
TEST(LaCbsTargetCandidates, OptimalWithFewerNodesWhereARobotParksInACorridor) {
  const World w = corridorToATarget();
  const Outcome o = solveCbs(w, true);
  ASSERT_TRUE(solvedValidly(o)) << describe(o);
  EXPECT_EQ(o.soc, 46);
  EXPECT_LE(o.result.stats.high_level_nodes, 600);  // a work count, not a time
}

TEST(LaCbsTargetCandidates, SameOptimumAsExhaustiveSearchAndWithout) {
  const World w = corridorToATarget();
  EXPECT_EQ(exhaustiveOptimalSoc(w.map, w.instance), 46);
  // Off by name, as `--backend-param la_cbs.target_candidates=0` sets it.
  auto solver = makeSolver("la_cbs", {{"la_cbs", {{"target_candidates", 0}}}});
  const Outcome without = solveWith(*solver, w, allRobots(w, 300.0));
  ASSERT_TRUE(solvedValidly(without)) << describe(without);
  EXPECT_EQ(without.soc, 46);
  EXPECT_GT(without.result.stats.high_level_nodes, 600);
}

}  // namespace
}  // namespace fleet_planner::test
