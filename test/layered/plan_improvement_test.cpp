// Plan compression and refinement: hand-made plans with waits and detours that can go, and
// waits that must stay; on random instances, both keep plans valid and never raise a cost.
#include <gtest/gtest.h>

#include <iostream>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/layered/plan_compression.h"
#include "fleet_planner/layered/plan_refinement.h"
#include "fleet_planner/layered/layered_planner.h"
#include "random_worlds.h"
#include "test_maps.h"
#include "test_robots.h"

namespace fleet_planner {
namespace {

using test::dot;
using test::footprintsOf;

// The path from `start` doing `actions` in turn.
Path pathOf(GridPose start, const std::vector<Action>& actions) {
  Path p{start};
  for (Action a : actions) p.push_back(applyAction(p.back(), a));
  return p;
}

// The heading whose forward move goes one cell towards +y.
int headingUp() {
  for (int h = 0; h < 4; ++h) {
    if (applyAction({0, 0, h}, Action::Forward).y == 1) return h;
  }
  return -1;
}

Plan planOf(std::vector<Path> paths) {
  Plan plan;
  plan.paths = std::move(paths);
  return plan;
}

long long socOf(const Instance& in, const Plan& plan) {
  std::vector<GridPose> targets;
  for (const Robot& r : in.robots) targets.push_back(r.target);
  return planMetrics(plan, targets).soc;
}

TEST(PlanCompression, DropsUselessWaitsAndKeepsNeededOnes) {
  // c crosses row 1 at column 4 during steps 0 and 1; a, just left of it, must not move into
  // (4, 1) before step 2. a's given path waits 5 steps: 2 are needed, 3 are not.
  const GridMap map = test::freeMap(8, 3);
  const int up = headingUp();
  ASSERT_GE(up, 0);
  Instance in;
  in.robots = {dot("a", {3, 1, 0}, {5, 1, 0}), dot("c", {4, 0, up}, {4, 2, up})};
  const Path a = pathOf({3, 1, 0}, {Action::Wait, Action::Wait, Action::Wait, Action::Wait, Action::Wait,
                                    Action::Forward, Action::Forward});
  const Path c = pathOf({4, 0, up}, {Action::Forward, Action::Forward});
  ASSERT_EQ(a.back(), in.robots[0].target);
  ASSERT_EQ(c.back(), in.robots[1].target);
  Plan plan = planOf({a, c});
  ASSERT_TRUE(validatePlan(map, in, plan).valid());
  const FleetGraphs graphs(map, footprintsOf(in));

  const CompressionStats stats = compressPlan(in, graphs, plan.paths, Deadline::in(5));
  const ValidationResult check = validatePlan(map, in, plan);
  EXPECT_TRUE(check.valid()) << check.violation.message;
  EXPECT_EQ(stats.waits_removed, 3);
  EXPECT_EQ(pathCost(plan.paths[0], in.robots[0].target), 4);  // two waits, two moves
  EXPECT_EQ(plan.paths[1], c);
}

TEST(PlanRefinement, ReplacesADetourByTheShortestPath) {
  // a's given path leaves row 2 and comes back (cost 13); nothing stands in the way of the
  // straight path (cost 7). b stands still in a far corner.
  const GridMap map = test::freeMap(9, 5);
  Instance in;
  in.robots = {dot("a", {0, 2, 0}, {7, 2, 0}), dot("b", {8, 4, 0}, {8, 4, 0})};
  using A = Action;
  const Path detour = pathOf({0, 2, 0}, {A::Forward, A::Forward, A::RotateCcw, A::Forward, A::RotateCw, A::Forward,
                                         A::Forward, A::Forward, A::RotateCw, A::Forward, A::RotateCcw, A::Forward,
                                         A::Forward});
  ASSERT_EQ(detour.back(), in.robots[0].target);
  Plan plan = planOf({detour, {in.robots[1].start}});
  ASSERT_TRUE(validatePlan(map, in, plan).valid());
  const FleetGraphs graphs(map, footprintsOf(in));

  const RefinementStats stats = refinePlan(in, graphs, plan.paths, Deadline::in(5));
  const ValidationResult check = validatePlan(map, in, plan);
  EXPECT_TRUE(check.valid()) << check.violation.message;
  EXPECT_EQ(pathCost(plan.paths[0], in.robots[0].target), 7);
  EXPECT_EQ(stats.soc_saved, 6);
  EXPECT_EQ(stats.improved, 1);
}

TEST(PlanRefinement, KeepsAPathThatOthersForce) {
  // A one-row corridor: b, right in front of a, moves on at once; a cannot follow in the same
  // step (their sweeps would share b's start cell), so its one wait is the best it can do, and
  // refinement must change nothing.
  const GridMap map = test::mapFromRows({"........"});
  Instance in;
  in.robots = {dot("a", {0, 0, 0}, {3, 0, 0}), dot("b", {1, 0, 0}, {7, 0, 0})};
  using A = Action;
  const Path a = pathOf({0, 0, 0}, {A::Wait, A::Forward, A::Forward, A::Forward});
  const Path b = pathOf({1, 0, 0}, {A::Forward, A::Forward, A::Forward, A::Forward, A::Forward, A::Forward});
  Plan plan = planOf({a, b});
  ASSERT_TRUE(validatePlan(map, in, plan).valid());
  const FleetGraphs graphs(map, footprintsOf(in));
  const RefinementStats stats = refinePlan(in, graphs, plan.paths, Deadline::in(5));
  EXPECT_EQ(stats.improved, 0);
  EXPECT_EQ(plan.paths[0], a);
  EXPECT_EQ(plan.paths[1], b);
}

TEST(PlanRefinement, FindsALongWaitInAFewNodes) {
  // A corridor (row 0) with one side pocket above column 5. b stands in the corridor at column
  // 5 until step 30, then backs into the pocket. a's given path waits 40 steps at its start
  // (cost 50); the cheapest drives to column 4, waits there until b has gone and arrives at
  // step 37. Refinement's search (safe intervals) takes the wait as one node, within a budget
  // of nodes that a search over every step of the wait cannot cover. (b's own wait is not
  // needed: in the same pass b then goes at once, and a later pass would let a go at once too.)
  const GridMap map = test::mapFromRows({"...........", "@@@@@.@@@@@"});
  const int up = headingUp();
  ASSERT_GE(up, 0);
  Instance in;
  in.robots = {dot("a", {0, 0, 0}, {10, 0, 0}), dot("b", {5, 0, up}, {5, 1, up})};
  std::vector<Action> waits_then_go(40, Action::Wait);
  waits_then_go.insert(waits_then_go.end(), 10, Action::Forward);
  std::vector<Action> b_actions(30, Action::Wait);
  b_actions.push_back(Action::Forward);
  Plan plan = planOf({pathOf({0, 0, 0}, waits_then_go), pathOf({5, 0, up}, b_actions)});
  ASSERT_TRUE(validatePlan(map, in, plan).valid());
  const FleetGraphs graphs(map, footprintsOf(in));
  RefinementOptions options;
  options.max_nodes_per_search = 100;
  options.max_passes = 1;
  options.group_size = 0;
  const RefinementStats stats = refinePlan(in, graphs, plan.paths, Deadline::in(5), options);
  const ValidationResult check = validatePlan(map, in, plan);
  EXPECT_TRUE(check.valid()) << check.violation.message;
  EXPECT_EQ(pathCost(plan.paths[0], in.robots[0].target), 37);
  EXPECT_EQ(pathCost(plan.paths[1], in.robots[1].target), 1);
  EXPECT_EQ(stats.soc_saved, 13 + 30);
}

// The heading whose forward move goes one cell towards -y.
int headingDown() {
  for (int h = 0; h < 4; ++h) {
    if (applyAction({0, 0, h}, Action::Forward).y == -1) return h;
  }
  return -1;
}

TEST(PlanRefinement, SearchesFirstTheRobotThatCanGainMost) {
  // b drives down column 3, over a's target (3, 2) at step 20, after 17 waits it need not make;
  // a arrives at its target right after b has left it, at the earliest it can (step 22). Both
  // cost 22; with the budget of a single search, the refinement spends it on b.
  const GridMap map = test::freeMap(8, 6);
  const int down = headingDown();
  ASSERT_GE(down, 0);
  Instance in;
  in.robots = {dot("a", {0, 2, 0}, {3, 2, 0}), dot("b", {3, 5, down}, {3, 0, down})};
  std::vector<Action> a_actions(19, Action::Wait), b_actions(17, Action::Wait);
  a_actions.insert(a_actions.end(), 3, Action::Forward);
  b_actions.insert(b_actions.end(), 5, Action::Forward);
  const Path a = pathOf(in.robots[0].start, a_actions);
  Plan plan = planOf({a, pathOf(in.robots[1].start, b_actions)});
  ASSERT_EQ(plan.paths[0].back(), in.robots[0].target);
  ASSERT_EQ(plan.paths[1].back(), in.robots[1].target);
  ASSERT_TRUE(validatePlan(map, in, plan).valid());
  const FleetGraphs graphs(map, footprintsOf(in));
  RefinementOptions options;
  options.max_expansions = 1;
  options.max_passes = 1;
  options.group_size = 0;
  const RefinementStats stats = refinePlan(in, graphs, plan.paths, Deadline::in(5), options);
  const ValidationResult check = validatePlan(map, in, plan);
  EXPECT_TRUE(check.valid()) << check.violation.message;
  EXPECT_EQ(stats.searches, 1);
  EXPECT_EQ(stats.improved, 1);
  EXPECT_EQ(pathCost(plan.paths[1], in.robots[1].target), 5);
  EXPECT_EQ(plan.paths[0], a);
}

TEST(PlanRefinement, DoesNotRepeatASearchThatFailedOnTheSamePaths) {
  // Two rooms. In the lower one a makes a detour that can go (cost 13, shortest 7); in the
  // upper one c drives round d, who stands on its target for good (cost 12: the cheapest way
  // round). Pass 1 improves a and then searches c in vain; pass 2 has nothing to search: a is
  // at its shortest, and c's search would run on the same paths as the one that failed.
  const GridMap map =
      test::mapFromRows({".........", ".........", ".........", "@@@@@@@@@", ".........", ".........", "........."});
  Instance in;
  in.robots = {dot("a", {0, 5, 0}, {7, 5, 0}), dot("c", {0, 1, 0}, {6, 1, 0}), dot("d", {3, 1, 0}, {3, 1, 0})};
  using A = Action;
  const std::vector<Action> round = {A::Forward, A::Forward, A::RotateCcw, A::Forward, A::RotateCw, A::Forward,
                                     A::Forward, A::RotateCw, A::Forward, A::RotateCcw, A::Forward, A::Forward};
  std::vector<Action> detour = round;
  detour.insert(detour.begin() + 5, A::Forward);  // three cells along the other row instead of two
  const Path c = pathOf(in.robots[1].start, round);
  Plan plan = planOf({pathOf(in.robots[0].start, detour), c, {in.robots[2].start}});
  ASSERT_EQ(plan.paths[0].back(), in.robots[0].target);
  ASSERT_EQ(plan.paths[1].back(), in.robots[1].target);
  ASSERT_TRUE(validatePlan(map, in, plan).valid());
  const FleetGraphs graphs(map, footprintsOf(in));
  RefinementOptions options;
  options.group_size = 0;
  const RefinementStats stats = refinePlan(in, graphs, plan.paths, Deadline::in(5), options);
  EXPECT_TRUE(validatePlan(map, in, plan).valid());
  EXPECT_EQ(pathCost(plan.paths[0], in.robots[0].target), 7);
  EXPECT_EQ(plan.paths[1], c);
  EXPECT_EQ(stats.passes, 2);
  EXPECT_EQ(stats.searches, 2);  // a and c in pass 1
}

// The turn (RotateCcw or RotateCw) from heading `from` to heading `to`, 90 degrees apart.
Action turn(int from, int to) {
  return applyAction({0, 0, from}, Action::RotateCcw).heading == to ? Action::RotateCcw : Action::RotateCw;
}

TEST(PlanRefinement, ReplansAGroupInTurnWhereNoRobotAloneCan) {
  // A corridor (row 5) with a pocket below column 3, and a loop round above it. j stands on its
  // target in the corridor, facing the pocket; i drives round the loop (cost 28). Neither can
  // do better alone: i cannot pass j, and j costs nothing. Together they can: i straight along
  // the corridor (14) while j backs into the pocket and comes back (7).
  const GridMap map = test::mapFromRows({"...............", ".@@@@@@@@@@@@@.", ".@@@@@@@@@@@@@.",
                                         ".@@@@@@@@@@@@@.", ".@@@@@@@@@@@@@.", "...............",
                                         "@@@.@@@@@@@@@@@"});
  const int up = headingUp(), down = headingDown();
  ASSERT_GE(up, 0);
  ASSERT_GE(down, 0);
  Instance in;
  in.robots = {dot("i", {0, 5, 0}, {14, 5, 0}), dot("j", {3, 5, up}, {3, 5, up})};
  std::vector<Action> loop = {turn(0, down)};
  loop.insert(loop.end(), 5, Action::Forward);
  loop.push_back(turn(down, 0));
  loop.insert(loop.end(), 14, Action::Forward);
  loop.push_back(turn(0, up));
  loop.insert(loop.end(), 5, Action::Forward);
  loop.push_back(turn(up, 0));
  Plan plan = planOf({pathOf(in.robots[0].start, loop), {in.robots[1].start}});
  ASSERT_EQ(plan.paths[0].back(), in.robots[0].target);
  ASSERT_EQ(pathCost(plan.paths[0], in.robots[0].target), 28);
  ASSERT_TRUE(validatePlan(map, in, plan).valid());
  const FleetGraphs graphs(map, footprintsOf(in));
  const RefinementStats stats = refinePlan(in, graphs, plan.paths, Deadline::in(5));
  const ValidationResult check = validatePlan(map, in, plan);
  EXPECT_TRUE(check.valid()) << check.violation.message;
  EXPECT_EQ(pathCost(plan.paths[0], in.robots[0].target), 14);
  EXPECT_EQ(pathCost(plan.paths[1], in.robots[1].target), 7);
  EXPECT_EQ(stats.soc_saved, 7);
  EXPECT_GE(stats.group_searches, 1);
}

// Refinement's budget of expansions holds for its group searches too: a search that starts
// within the budget may run past it by its own limit at most (the budget is checked before each
// search, a group's member searches included).
TEST(PlanRefinement, GroupSearchesStayWithinTheBudget) {
  int grouped = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const GridMap map = test::randomMap(seed, 14, 12, 6, 10);
    const std::optional<Instance> fleet = test::randomFleet(map, 3 + static_cast<int>(seed % 5), seed);
    if (!fleet) continue;
    const FleetGraphs graphs(map, footprintsOf(*fleet));
    LayeredOptions plain;
    plain.backend = "la_lacam";
    plain.refine = plain.compress = false;
    plain.seed = seed;
    LayeredResult merged = planLayered(map, *fleet, graphs, plain, Deadline::in(0.5));
    if (!merged.success()) continue;
    RefinementOptions options;
    options.max_nodes_per_search = 100;
    options.max_expansions = 300;
    const RefinementStats stats = refinePlan(*fleet, graphs, merged.plan.paths, Deadline::in(5), options);
    EXPECT_LE(stats.expansions, options.max_expansions + options.max_nodes_per_search)
        << "seed " << seed;
    grouped += stats.group_searches > 0;
    const ValidationResult check = validatePlan(map, *fleet, merged.plan);
    EXPECT_TRUE(check.valid()) << "seed " << seed << ": " << check.violation.message;
  }
  EXPECT_GT(grouped, 3) << grouped;
  std::cout << "[ grouped   ] " << grouped << "\n";
}

// On seeded random instances, the layered planner with refinement and compression returns valid
// plans whose SOC and makespan are never above those it returns without them.
TEST(PlanImprovement, NeverWorseThanTheMergedPlan) {
  int compared = 0, improved = 0;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    const GridMap map = test::randomMap(seed, 14, 12, 6, 10);
    const std::optional<Instance> fleet = test::randomFleet(map, 3 + static_cast<int>(seed % 5), seed);
    if (!fleet) continue;
    const Instance& in = *fleet;
    const FleetGraphs graphs(map, footprintsOf(in));
    for (const char* backend : {"la_cbs", "la_lacam"}) {
      LayeredOptions plain;
      plain.backend = backend;
      plain.refine = plain.compress = false;
      plain.seed = seed;
      LayeredOptions better = plain;
      better.refine = better.compress = true;
      const LayeredResult a = planLayered(map, in, graphs, plain, Deadline::in(0.5));
      const LayeredResult b = planLayered(map, in, graphs, better, Deadline::in(0.5));
      if (!a.success() || !b.success()) continue;
      ++compared;
      const ValidationResult check = validatePlan(map, in, b.plan);
      ASSERT_TRUE(check.valid()) << "seed " << seed << " " << backend << ": " << check.violation.message;
      EXPECT_LE(b.metrics.soc, a.metrics.soc) << "seed " << seed << " " << backend;
      EXPECT_LE(b.metrics.makespan, a.metrics.makespan) << "seed " << seed << " " << backend;
      EXPECT_EQ(b.metrics.soc, socOf(in, b.plan));
      if (b.metrics.soc < a.metrics.soc) ++improved;
    }
  }
  EXPECT_GE(compared, 60);
  EXPECT_GT(improved, 0);
  std::cout << "[ improve   ] " << improved << " of " << compared << " plans improved\n";
}

}  // namespace
}  // namespace fleet_planner
