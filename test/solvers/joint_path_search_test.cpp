// The joint search of LA-LNS's knots (joint_path_search.h): its sum of costs against the
// independent exhaustive search on random tiny instances, its proof that a group has no plan,
// and the knot that replanning robot by robot cannot untie. Every plan goes through the
// validator.
#include <gtest/gtest.h>

#include "exhaustive_search.h"
#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/runtime/random.h"
#include "fleet_planner/solvers/search/joint_path_search.h"
#include "fleet_planner/solvers/registry.h"
#include "fleet_planner/solvers/search/search_space.h"
#include "fleet_planner/solvers/search/solve_common.h"
#include "solver_test_util.h"
#include "test_maps.h"
#include "tiny_worlds.h"

namespace fleet_planner::test {
namespace {

std::vector<int> everyAgent(const SearchSpace& space) {
  std::vector<int> group(space.numAgents());
  for (int a = 0; a < space.numAgents(); ++a) group[a] = a;
  return group;
}

JointSearchResult searchAll(const Subproblem& sub) {
  const SearchSpace space(sub);
  const SoftPathTable empty(space);
  JointSearchOptions options;
  options.max_nodes = 40'000'000;  // well beyond the exhaustive reference's 4,000,000 states
  return jointPathSearch(space, everyAgent(space), empty, sub.deadline, options);
}

// The plan of a search over every robot of the world (instance order), through the validator.
::testing::AssertionResult validJointPlan(const World& w, const Subproblem& sub,
                                          const JointSearchResult& r, long long& soc) {
  const SearchSpace space(sub);
  Plan plan;
  plan.paths = toPosePaths(space, r.paths);
  const ValidationResult v = validatePlan(w.map, w.instance, plan);
  if (!v.valid()) return ::testing::AssertionFailure() << v.violation.message;
  soc = planMetrics(plan, w.targets()).soc;
  return ::testing::AssertionSuccess();
}

// With nothing outside the group, the search is an optimal joint search: it finds a plan exactly
// when the exhaustive reference does, of the same (optimal) sum of costs, and proves the rest.
TEST(JointPathSearch, SocEqualsExhaustiveOptimumOnRandomTinyInstances) {
  Rng rng(11);
  int solved = 0, proven = 0;
  for (int round = 0; round < 200; ++round) {
    const std::unique_ptr<World> w = randomTinyWorld(rng, round % 3 == 0 ? 3 : 2);
    const ExhaustiveResult best = exhaustiveSearch(w->map, w->instance, 4'000'000);
    if (best.budget_exhausted) continue;
    const Subproblem sub = allRobots(*w);
    const JointSearchResult r = searchAll(sub);
    SCOPED_TRACE("round " + std::to_string(round));
    if (best.soc < 0) {
      EXPECT_EQ(r.outcome, JointSearchResult::Outcome::NoPath);
      ++proven;
      continue;
    }
    ASSERT_EQ(r.outcome, JointSearchResult::Outcome::Found);
    long long soc = -1;
    ASSERT_TRUE(validJointPlan(*w, sub, r, soc));
    EXPECT_EQ(soc, best.soc);
    EXPECT_EQ(r.collisions, 0);
    ++solved;
  }
  EXPECT_GT(solved, 80);
  EXPECT_GT(proven, 60);
}

// A and B swap along a corridor whose only pocket holds C, at its target: C backs down the stem,
// one of A and B waits in the pocket, and C comes back. Replanned one by one, C has no reason to
// move and A and B each prefer one colliding step to a detour.
TEST(JointPathSearch, UntiesThreeRobotKnot) {
  const World w(mapFromRows({".......", "@@@.@@@", "@@@.@@@"}),
                {dot("A", {0, 0, 0}, {6, 0, 0}), dot("B", {6, 0, 1}, {0, 0, 1}), dot("C", {3, 1, 2}, {3, 1, 2})});
  const Subproblem sub = allRobots(w);
  const JointSearchResult r = searchAll(sub);
  ASSERT_EQ(r.outcome, JointSearchResult::Outcome::Found);
  long long soc = -1;
  ASSERT_TRUE(validJointPlan(w, sub, r, soc));
  const ExhaustiveResult best = exhaustiveSearch(w.map, w.instance);
  EXPECT_EQ(soc, best.soc);
}

// Without a pocket the swap has no plan, and the search says so once the joint space is
// exhausted, long before its expansion budget.
TEST(JointPathSearch, SwapWithoutPocketIsProvenImpossible) {
  const World w(freeMap(6, 1), {dot("a", {0, 0, 0}, {5, 0, 0}), dot("b", {5, 0, 1}, {0, 0, 1})});
  const JointSearchResult r = searchAll(allRobots(w));
  EXPECT_EQ(r.outcome, JointSearchResult::Outcome::NoPath);
  EXPECT_LT(r.expansions, 10'000);
}

// An agent outside the group is a soft obstacle: parked in the only pocket, the swapping pair
// must pass through it and pays for it; as a hard static footprint it leaves no plan at all.
TEST(JointPathSearch, AgentsOutsideTheGroupAreSoft) {
  const World w(mapFromRows({".......", "@@@.@@@"}),
                {dot("a", {0, 0, 0}, {6, 0, 0}), dot("b", {6, 0, 1}, {0, 0, 1}), dot("p", {3, 1, 0}, {3, 1, 0})});
  Subproblem sub = allRobots(w);
  {
    const SearchSpace space(sub);
    SoftPathTable table(space);
    table.insert(2, {space.start(2)});
    const JointSearchResult r = jointPathSearch(space, {0, 1}, table, sub.deadline);
    ASSERT_EQ(r.outcome, JointSearchResult::Outcome::Found);
    EXPECT_GT(r.collisions, 0);
  }
  sub.robots = {0, 1};
  sub.blocked = {{2, {3, 1, 0}}};
  const JointSearchResult hard = searchAll(sub);
  EXPECT_EQ(hard.outcome, JointSearchResult::Outcome::NoPath);
}

// A search that starts later, from given states (JointSearchOptions::from): its paths begin at
// those states at that step, and joined to the members' ways there the plan is valid. In a
// static world, from the starts at any step it costs what the search from step 0 does.
TEST(JointPathSearch, StartsLaterFromTheStatesGiven) {
  const World w(mapFromRows({".......", "@@@.@@@"}),
                {dot("a", {0, 0, 0}, {6, 0, 0}), dot("b", {6, 0, 1}, {0, 0, 1})});
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  const SoftPathTable empty(space);
  const JointSearchResult first = jointPathSearch(space, {0, 1}, empty, sub.deadline);
  ASSERT_EQ(first.outcome, JointSearchResult::Outcome::Found);
  JointSearchOptions later;
  later.from = {space.start(0), space.start(1)};
  later.from_step = 7;
  const JointSearchResult same = jointPathSearch(space, {0, 1}, empty, sub.deadline, later);
  ASSERT_EQ(same.outcome, JointSearchResult::Outcome::Found);
  EXPECT_EQ(same.paths, first.paths);
  // a has driven two cells by step 2, b has waited at its start.
  const StateGraph& g = space.graph(0);
  const StatePath a_way = {g.id({0, 0, 0}), g.id({1, 0, 0}), g.id({2, 0, 0})};
  later.from = {a_way.back(), space.start(1)};
  later.from_step = 2;
  const JointSearchResult on = jointPathSearch(space, {0, 1}, empty, sub.deadline, later);
  ASSERT_EQ(on.outcome, JointSearchResult::Outcome::Found);
  ASSERT_EQ(on.paths[0].front(), a_way.back());
  ASSERT_EQ(on.paths[1].front(), space.start(1));
  JointSearchResult joined = on;
  joined.paths[0].insert(joined.paths[0].begin(), a_way.begin(), a_way.end() - 1);
  joined.paths[1].insert(joined.paths[1].begin(), 2, space.start(1));
  long long soc = -1;
  EXPECT_TRUE(validJointPlan(w, sub, joined, soc));
  EXPECT_GE(soc, 2);
  later.from = {space.start(0)};
  EXPECT_THROW(jointPathSearch(space, {0, 1}, empty, sub.deadline, later), InvalidInput);
}

// Joint states that differ only in a step after JointSearchOptions::static_from are one: a
// robot turning to and fro for 2,000 steps in a room of its own keeps the world changing, so
// the exact search must tell every step of the pair's impossible swap apart and runs out of
// states; told that nothing near the pair moves after step 0, it exhausts the swap's few joint
// states at once.
TEST(JointPathSearch, MergesStatesPastTheStepItIsGiven) {
  const World w(mapFromRows({"......@...", "@@@@@@@..."}),
                {dot("a", {0, 0, 0}, {5, 0, 0}), dot("b", {5, 0, 1}, {0, 0, 1}), dot("far", {8, 0, 0}, {8, 0, 0})});
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  SoftPathTable table(space);
  const StateGraph& g = space.graph(2);
  StatePath to_and_fro;
  for (int t = 0; t < 2000; ++t) to_and_fro.push_back(g.id({8, 0, t % 2 == 0 ? 0 : 2}));  // turning
  to_and_fro.push_back(g.id({8, 0, 0}));
  ASSERT_NE(to_and_fro[1], kNoState);
  table.insert(2, to_and_fro);
  JointSearchOptions options;
  options.max_nodes = 20'000;
  const JointSearchResult exact = jointPathSearch(space, {0, 1}, table, sub.deadline, options);
  EXPECT_EQ(exact.outcome, JointSearchResult::Outcome::NodeLimit);
  options.static_from = 0;
  const JointSearchResult merged = jointPathSearch(space, {0, 1}, table, sub.deadline, options);
  EXPECT_EQ(merged.outcome, JointSearchResult::Outcome::NoPath);
  EXPECT_LT(merged.expansions, 2'000);
}

TEST(JointPathSearch, RejectsGroupsLargerThanItsLimit) {
  const World w(freeMap(6, 2), {dot("a", {0, 0, 0}, {5, 0, 0}), dot("b", {1, 0, 0}, {4, 0, 0}),
                                dot("c", {0, 1, 0}, {5, 1, 0}), dot("d", {1, 1, 0}, {4, 1, 0})});
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  const SoftPathTable empty(space);
  EXPECT_THROW(jointPathSearch(space, {0, 1, 2, 3}, empty, sub.deadline), InvalidInput);
}

}  // namespace
}  // namespace fleet_planner::test
