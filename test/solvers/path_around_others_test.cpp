// ECBS's primal step (path_around_others.h): one robot planned around every other robot's whole
// path. On random tiny worlds the plan it makes with the others' paths passes the independent
// plan validator whenever it finds a path, and it finds one where the robot can wait for the
// others to pass.
#include <gtest/gtest.h>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/solvers/cbs/path_around_others.h"
#include "fleet_planner/solvers/search/solve_common.h"
#include "solver_test_util.h"
#include "test_maps.h"
#include "tiny_worlds.h"

namespace fleet_planner::test {
namespace {

// Each agent's shortest path alone (an empty path for agents before `first`); false if one of
// them has none.
bool pathsAlone(const SearchSpace& space, const Subproblem& sub, int first, std::vector<StatePath>& paths) {
  paths.assign(space.numAgents(), {});
  for (int a = first; a < space.numAgents(); ++a) {
    const LowLevelResult r = spaceTimeAStar(space, a, {}, sub.deadline);
    if (r.outcome != LowLevelResult::Outcome::Found) return false;
    paths[a] = r.path;
  }
  return true;
}

TEST(PathAroundOthers, PlansWithTheOthersPathsPassTheValidator) {
  Rng rng(7);
  int found = 0, waited = 0;
  for (int round = 0; round < 300; ++round) {
    const std::unique_ptr<World> w = randomTinyWorld(rng, round % 3 == 0 ? 3 : 2);
    const Subproblem sub = allRobots(*w);
    const SearchSpace space(sub);
    std::vector<StatePath> paths;
    if (!pathsAlone(space, sub, 1, paths) || countConflicts(space, paths) > 0) continue;  // the others must not meet
    const LowLevelResult mine = pathAroundOthers(space, 0, paths, sub.deadline, 1'000'000);
    if (mine.outcome != LowLevelResult::Outcome::Found) continue;
    const LowLevelResult free = spaceTimeAStar(space, 0, {}, sub.deadline);
    ASSERT_EQ(free.outcome, LowLevelResult::Outcome::Found);
    EXPECT_GE(mine.path.size(), free.path.size());
    waited += mine.path.size() > free.path.size();
    paths[0] = mine.path;
    Plan plan;
    plan.paths = toPosePaths(space, paths);
    const ValidationResult v = validatePlan(w->map, w->instance, plan);
    EXPECT_TRUE(v.valid()) << "round " << round << ": " << v.violation.message;
    ++found;
  }
  EXPECT_GT(found, 60);
  EXPECT_GT(waited, 10);
  std::cout << "[ around    ] " << found << " paths, " << waited << " longer than alone\n";
}

// b drives up a one-cell corridor across a's way; a must let it pass.
TEST(PathAroundOthers, WaitsForAnotherRobotToClearACorridor) {
  const World w(mapFromRows({"@@@@.@@@@", ".........", "@@@@.@@@@", "@@@@.@@@@"}),
                {dot("a", {3, 1, 0}, {8, 1, 0}), dot("b", {4, 3, 3}, {4, 0, 3})});
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  std::vector<StatePath> paths(2);
  paths[1] = spaceTimeAStar(space, 1, {}, sub.deadline).path;
  ASSERT_FALSE(paths[1].empty());
  paths[0] = spaceTimeAStar(space, 0, {}, sub.deadline).path;
  ASSERT_EQ(paths[0].size(), 6u);
  ASSERT_GT(countConflicts(space, paths), 0);  // straight through, a meets b in the corridor
  const LowLevelResult r = pathAroundOthers(space, 0, paths, sub.deadline, 100'000);
  ASSERT_EQ(r.outcome, LowLevelResult::Outcome::Found);
  paths[0] = r.path;
  Plan plan;
  plan.paths = toPosePaths(space, paths);
  const ValidationResult v = validatePlan(w.map, w.instance, plan);
  EXPECT_TRUE(v.valid()) << v.violation.message;
  EXPECT_GT(r.path.size(), 6u);
}

// Every robot's shortest path alone, then the conflicting ones planned around the others in
// turn: a plan that passes the validator whenever one is returned, each robot at least as
// long as alone; and one is returned on a fair part of the worlds where the robots meet.
TEST(PathAroundOthers, InTurnGivesPlansThatPassTheValidator) {
  Rng rng(11);
  int met = 0, planned = 0;
  for (int round = 0; round < 200; ++round) {
    const std::unique_ptr<World> w = randomTinyWorld(rng, 3);
    const Subproblem sub = allRobots(*w);
    const SearchSpace space(sub);
    std::vector<StatePath> alone;
    if (!pathsAlone(space, sub, 0, alone) || countConflicts(space, alone) == 0) continue;
    ++met;
    long long expansions = 0;
    const std::vector<StatePath> paths = aroundOthersInTurn(space, alone, sub.deadline, 1'000'000, expansions);
    if (paths.empty()) continue;
    EXPECT_GT(expansions, 0);
    ASSERT_EQ(paths.size(), alone.size());
    for (std::size_t a = 0; a < paths.size(); ++a) EXPECT_GE(paths[a].size(), alone[a].size());
    Plan plan;
    plan.paths = toPosePaths(space, paths);
    const ValidationResult v = validatePlan(w->map, w->instance, plan);
    EXPECT_TRUE(v.valid()) << "round " << round << ": " << v.violation.message;
    ++planned;
  }
  EXPECT_GT(met, 30);
  EXPECT_GT(planned, met / 4);  // cramped worlds: often a robot cannot let another pass
  std::cout << "[ in turn   ] " << planned << " of " << met << " worlds whose robots meet planned\n";
}

}  // namespace
}  // namespace fleet_planner::test
