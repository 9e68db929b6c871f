// The layered planner: valid and deterministic plans from both backends on seeded random
// instances, the paper's Figure 1 instances, and the safeguard that merges a failed subproblem.
#include "fleet_planner/layered/layered_planner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/solvers/registry.h"
#include "random_worlds.h"
#include "test_maps.h"
#include "test_robots.h"

namespace fleet_planner {
namespace {

using test::dot;
using test::footprintsOf;

LayeredResult plan(const GridMap& map, const Instance& in, const std::string& backend, bool layered = true,
                   double seconds = 5.0) {
  const FleetGraphs graphs(map, footprintsOf(in));
  LayeredOptions o;
  o.backend = backend;
  o.decompose = layered;
  return planLayered(map, in, graphs, o, Deadline::in(seconds));
}

GridMap randomMap(std::uint64_t seed) { return test::randomMap(seed, 16, 14, 8, 12); }

/// The robots of each subproblem as solved, in order: the partition after any merges (and,
/// after a -1, the robots that stepped aside for it).
std::vector<std::vector<int>> solvedPartition(const LayeredResult& r) {
  std::vector<std::vector<int>> parts;
  for (const auto& s : r.subproblems) {
    parts.push_back(s.robots);
    if (s.stepping_aside.empty()) continue;
    parts.back().push_back(-1);
    parts.back().insert(parts.back().end(), s.stepping_aside.begin(), s.stepping_aside.end());
  }
  return parts;
}

// Six robots of every footprint kind crossing an open 12 x 12 map (the conformance suite's mixed
// fleet): raw LA-CBS does not solve it within seconds, LA-LNS does in a fraction of one. With
// LA-LNS as the fallback the raw subproblem is solved in the second half of its time, validly,
// and reported as solved by the fallback.
TEST(LayeredFallback, FallbackSolvesWhatTheBackendCannot) {
  const GridMap map =
      test::mapFromRows({"......@.....", "............", "............", "............",
                         "............", "@....@......", "......@....@", "............",
                         "............", "............", "............", ".....@......"});
  Instance in;
  in.robots = {
      dot("c1", {0, 1, 0}, {11, 10, 1}),
      test::makeRobot("c2", Footprint::circle(0.9), {2, 9, 3}, {9, 2, 2}),
      test::makeRobot("b1", Footprint::block(-0.5, -0.5, 1.5, 0.5), {8, 9, 1}, {3, 2, 0}),
      test::makeRobot("p1", Footprint::polygon({{1, 0}, {-1, 1}, {-1, -1}}), {9, 5, 1}, {2, 6, 0}),
      dot("c3", {11, 1, 1}, {0, 10, 0}),
      test::makeRobot("b2", Footprint::block(-0.5, -0.5, 0.5, 1.5), {5, 9, 0}, {7, 3, 1})};
  const FleetGraphs graphs(map, footprintsOf(in));
  LayeredOptions o;
  o.backend = "la_cbs";
  o.decompose = false;
  const LayeredResult alone = planLayered(map, in, graphs, o, Deadline::in(3.0));
  EXPECT_FALSE(alone.success()) << "precondition: raw LA-CBS is expected to time out here";
  o.fallback = "la_lns";
  // LA-CBS uses its part of the share (it fails by time); LA-LNS needs 1-3 s of the rest under
  // the sanitizers, and more on a loaded machine: it gets four fifths of the share (about 7 s).
  o.budget.fallback_share = 0.8;
  const LayeredResult helped = planLayered(map, in, graphs, o, Deadline::in(10.0));
  ASSERT_TRUE(helped.success()) << helped.reason;
  EXPECT_TRUE(validatePlan(map, in, helped.plan).valid());
  ASSERT_EQ(helped.subproblems.size(), 1u);
  EXPECT_TRUE(helped.subproblems[0].by_fallback);
}

// Test-only serial backends: one that never finds a plan, and one that finds none around moving
// obstacles (it is LA-CBS otherwise).
class NeverSerial : public Solver {
 public:
  std::string name() const override { return "never_serial_test_backend"; }
  bool avoidsMovingObstacles() const override { return true; }
  SolveResult solve(const Subproblem&) override {
    SolveResult r;
    r.status = SolveStatus::Timeout;
    r.reason = "never plans";
    return r;
  }
};
class ShyOfMovingSerial : public Solver {
 public:
  std::string name() const override { return "shy_of_moving_test_backend"; }
  bool avoidsMovingObstacles() const override { return true; }
  SolveResult solve(const Subproblem& p) override {
    if (p.moving.empty()) return makeSolver("la_cbs")->solve(p);
    SolveResult r;
    r.status = SolveStatus::Timeout;
    r.reason = "shy of moving obstacles";
    return r;
  }
};
const bool kNeverSerial =
    registerSolver("never_serial_test_backend", [] { return std::make_unique<NeverSerial>(); });
const bool kShyOfMoving = registerSolver("shy_of_moving_test_backend",
                                         [] { return std::make_unique<ShyOfMovingSerial>(); });

// Paper Figure 1 B: a1's level plans around a2's path. The backend fails both levels; the
// fallback fails around a2's moving path as well (a serial one that finds nothing around moving
// obstacles; LA-LaCAM, a parallel one, cannot take them at all), so, as the backend would be,
// it is tried with a2 at its target and its plan delayed until it fits: both levels are solved
// by the fallback, with no robot stepping aside and no merge, and the plan is valid.
TEST(LayeredFallback, FallbackIsDelayedAroundTheChainLikeTheBackend) {
  ASSERT_TRUE(kNeverSerial && kShyOfMoving);
  const GridMap map = test::mapFromRows({"@.@", "...", "@.@"});
  Instance in;
  in.robots = {dot("a1", {1, 2, 3}, {1, 1, 3}), dot("a2", {0, 1, 0}, {2, 1, 0})};
  const FleetGraphs graphs(map, footprintsOf(in));
  for (const char* fallback : {"shy_of_moving_test_backend", "la_lacam"}) {
    SCOPED_TRACE(fallback);
    LayeredOptions o;
    o.backend = "never_serial_test_backend";
    o.fallback = fallback;
    const LayeredResult r = planLayered(map, in, graphs, o, Deadline::in(5.0));
    ASSERT_TRUE(r.success()) << r.reason;
    EXPECT_TRUE(validatePlan(map, in, r.plan).valid());
    EXPECT_TRUE(r.step_asides.empty()) << r.step_asides.front();
    EXPECT_TRUE(r.merges.empty()) << r.merges.front();
    ASSERT_EQ(r.subproblems.size(), 2u);
    EXPECT_EQ(r.subproblems[0].robots, std::vector<int>{1});
    for (const auto& s : r.subproblems) EXPECT_TRUE(s.by_fallback) << s.reason;
    EXPECT_FALSE(r.subproblems[0].delayed_in_cluster);
    EXPECT_TRUE(r.subproblems[1].delayed_in_cluster);
  }
}

class LayeredBackends : public ::testing::TestWithParam<std::string> {};

// Some subproblem's plan is the one its search had when its limit stopped it (LA-CBS's
// anytime answer): a plan that depends on where the deadline cut in.
bool stoppedEarly(const LayeredResult& r) {
  return std::any_of(r.subproblems.begin(), r.subproblems.end(),
                     [](const SolvedSubproblem& s) { return s.stopped_early; });
}

// 500 seeded random instances per backend (1000 plans in all): every returned plan is valid,
// and on every tenth seed a second run gives the same plan. Instances are only individually
// solvable (as the paper's generator makes them), so some are jointly unsolvable or too hard
// for the short limit: how many get solved is a benchmark figure, not asserted here beyond
// "most" (timing on a loaded machine must not make this test flaky). For the same reason the
// rerun is compared only when it solved the same subproblems: a subproblem whose time share ran
// out in the short run is merged by the safeguard (or decomposition stopped early), which
// legitimately gives another plan; that happens on a slow machine or under sanitizers.
TEST_P(LayeredBackends, RandomInstancesGiveValidDeterministicPlans) {
  int solved = 0, tried = 0, compared = 0, repartitioned = 0;
  for (std::uint64_t seed = 1; seed <= 500; ++seed) {
    const GridMap map = randomMap(seed);
    const std::optional<Instance> fleet = test::randomFleet(map, 2 + static_cast<int>(seed % 6), seed);
    if (!fleet) continue;
    const Instance& in = *fleet;
    ++tried;
    const LayeredResult a = plan(map, in, GetParam(), true, 0.25);
    if (!a.success()) {
      EXPECT_FALSE(a.reason.empty()) << "seed " << seed << ": a failure must say why";
      continue;
    }
    ++solved;
    const ValidationResult v = validatePlan(map, in, a.plan);
    EXPECT_TRUE(v.valid()) << "seed " << seed << ": " << v.violation.message;
    // Same input, same plan, unless the deadline cut the plan's improvement short or stopped a
    // subproblem's search with the plan it had (LA-CBS's anytime answer).
    if (seed % 10 == 0 && !a.refinement.deadline_hit && !a.compression.deadline_hit && !stoppedEarly(a)) {
      const LayeredResult b = plan(map, in, GetParam(), true, 5.0);
      if (b.success() && solvedPartition(a) != solvedPartition(b)) {
        ++repartitioned;
      } else if (b.success()) {
        ++compared;
        EXPECT_EQ(a.plan.paths, b.plan.paths) << "seed " << seed << ": not deterministic";
      }
    }
  }
  EXPECT_GE(tried, 450);
  EXPECT_GE(compared, 20);
  EXPECT_GE(solved, tried / 2) << GetParam() << " solved " << solved << " of " << tried;
  std::cout << "[ random    ] " << GetParam() << ": " << solved << " of " << tried << " solved within 0.25 s, "
            << compared << " rerun identical, " << repartitioned << " rerun with other subproblems\n";
}

// Independent subproblems (LA-LaCAM) or clusters (LA-CBS) run on a thread pool: one thread or
// three give the same plan. Runs where a subproblem ran out of its time share and was merged
// are left out: that depends on the machine's speed (it happens under ASan), not on threads.
TEST_P(LayeredBackends, ThreadsDoNotChangeThePlan) {
  int compared = 0;
  for (std::uint64_t seed = 1; seed <= 160 && compared < 15; ++seed) {
    const GridMap map = randomMap(seed + 1000);
    const std::optional<Instance> fleet = test::randomFleet(map, 4 + static_cast<int>(seed % 5), seed);
    if (!fleet) continue;
    const Instance& in = *fleet;
    const FleetGraphs graphs(map, footprintsOf(in));
    LayeredOptions o;
    o.backend = GetParam();
    o.seed = seed;
    o.threads = 1;
    const LayeredResult one = planLayered(map, in, graphs, o, Deadline::in(1.0));
    o.threads = 3;
    const LayeredResult three = planLayered(map, in, graphs, o, Deadline::in(1.0));
    if (!one.success() || !three.success() || one.refinement.deadline_hit || three.refinement.deadline_hit) continue;
    if (stoppedEarly(one) || stoppedEarly(three)) continue;  // where the deadline stopped a search
    if (!one.merges.empty() || !three.merges.empty() || !one.step_asides.empty() || !three.step_asides.empty()) continue;
    ++compared;
    EXPECT_EQ(one.plan.paths, three.plan.paths) << "seed " << seed;
    EXPECT_EQ(one.subproblems.size(), three.subproblems.size()) << "seed " << seed;
  }
  EXPECT_GE(compared, 12);
}

TEST_P(LayeredBackends, FigureOneBSolvesWithA2First) {
  // Paper Figure 1 B on a plus-shaped map: a2 crosses through a1's target, so a2 goes first.
  const GridMap map = test::mapFromRows({"@.@", "...", "@.@"});
  Instance in;
  in.robots = {dot("a1", {1, 2, 3}, {1, 1, 3}), dot("a2", {0, 1, 0}, {2, 1, 0})};
  const LayeredResult r = plan(map, in, GetParam());
  ASSERT_TRUE(r.success()) << r.reason;
  ASSERT_EQ(r.subproblems.size(), 2u);
  EXPECT_EQ(r.subproblems[0].robots, std::vector<int>{1});
  EXPECT_TRUE(validatePlan(map, in, r.plan).valid());
}

INSTANTIATE_TEST_SUITE_P(Backends, LayeredBackends, ::testing::Values("la_cbs", "la_lacam"));

// A test-only backend that fails any subproblem in which a robot named "stubborn" is the only
// one to reach a target (others may step aside), and is LA-LaCAM otherwise: the planner must
// try it with the robots nearby stepping aside, then merge it with a neighbour, and succeed.
class Stubborn : public Solver {
 public:
  std::string name() const override { return "stubborn_test_backend"; }
  bool avoidsMovingObstacles() const override { return false; }
  SolveResult solve(const Subproblem& p) override {
    if (p.robots.size() == p.returning.size() + 1 && p.instance->robots[p.robots[0]].id == "stubborn") {
      SolveResult r;
      r.status = SolveStatus::Infeasible;
      r.reason = "refuses to plan alone";
      return r;
    }
    return makeSolver("la_lacam")->solve(p);
  }
};
const bool kStubborn = registerSolver("stubborn_test_backend", [] { return std::make_unique<Stubborn>(); });

TEST(LayeredPlanner, FailedSubproblemIsMergedWithItsNeighbour) {
  ASSERT_TRUE(kStubborn);
  const GridMap map = test::freeMap(12, 6);
  Instance in;
  in.robots = {dot("a", {0, 0, 0}, {11, 0, 0}), dot("stubborn", {0, 3, 0}, {11, 3, 0}), dot("c", {0, 5, 0}, {11, 5, 0})};
  const LayeredResult r = plan(map, in, "stubborn_test_backend");
  ASSERT_TRUE(r.success()) << r.reason;
  ASSERT_EQ(r.step_asides.size(), 1u);
  EXPECT_NE(r.step_asides[0].find("stubborn"), std::string::npos) << r.step_asides[0];
  ASSERT_EQ(r.merges.size(), 1u);
  EXPECT_NE(r.merges[0].find("stubborn"), std::string::npos) << r.merges[0];
  EXPECT_NE(r.merges[0].find("refuses to plan alone"), std::string::npos) << r.merges[0];
  EXPECT_EQ(r.subproblems.size(), r.decomposition.subproblems.size() - 1);
  EXPECT_TRUE(validatePlan(map, in, r.plan).valid());
}

// A and B swap along a corridor whose only pocket, the top of a two-cell stem, holds C (start
// and target). Each of A and B can pass C alone, so C is a subproblem of its own and the level
// {A, B} sees it as an obstacle: no pocket is left and that level fails (LA-LNS proves it). Solved
// again with C free to step aside, C backs down the stem, one of A and B waits in the pocket, and
// C comes back: C's plan is its own (empty) one followed by the step aside, and the whole plan is
// valid. (LA-CBS does not solve this three-robot knot even raw, see the README.)
TEST(LayeredStepAside, StandingRobotStepsAsideForAFailedLevel) {
  const GridMap map = test::mapFromRows({".......", "@@@.@@@", "@@@.@@@"});
  Instance in;
  in.robots = {dot("A", {0, 0, 0}, {6, 0, 0}), dot("B", {6, 0, 1}, {0, 0, 1}), dot("C", {3, 1, 2}, {3, 1, 2})};
  for (const std::string backend : {"la_lacam", "la_lns"}) {
    SCOPED_TRACE(backend);
    const LayeredResult r = plan(map, in, backend, true, 3.0);
    ASSERT_TRUE(r.success()) << r.reason;
    EXPECT_TRUE(validatePlan(map, in, r.plan).valid());
    ASSERT_EQ(r.step_asides.size(), 1u);
    EXPECT_TRUE(r.merges.empty()) << r.merges.front();
    bool helped = false;
    for (const auto& s : r.subproblems) helped = helped || s.stepping_aside == std::vector<int>{2};
    EXPECT_TRUE(helped);
    const Path& c = r.plan.paths[2];
    EXPECT_TRUE(std::any_of(c.begin(), c.end(), [](const GridPose& p) { return p.y == 2; })) << "C never stepped aside";
    EXPECT_EQ(c.back(), (GridPose{3, 1, 2}));
  }
}

// A test-only backend that gives up whenever it may (Subproblem::may_give_up) and is LA-LaCAM
// otherwise; it notes what it was asked.
struct Ask {
  std::size_t robots, returning;
  bool may_give_up;
};
std::vector<Ask> asked;
class GivesUp : public Solver {
 public:
  std::string name() const override { return "gives_up_test_backend"; }
  bool avoidsMovingObstacles() const override { return false; }
  SolveResult solve(const Subproblem& p) override {
    const bool may_give_up = p.may_give_up && p.may_give_up();
    asked.push_back({p.robots.size(), p.returning.size(), may_give_up});
    if (!may_give_up) return makeSolver("la_lacam")->solve(p);
    SolveResult r;
    r.status = SolveStatus::Timeout;
    r.reason = "stuck";
    return r;
  }
};
const bool kGivesUp = registerSolver("gives_up_test_backend", [] { return std::make_unique<GivesUp>(); });

// The knot above: the first attempt at {A, B}, with C standing near, may give up early (C may
// step aside then); the attempt with C stepping aside may not (only a merge would be left), nor
// may C's own subproblem of one robot.
TEST(LayeredStepAside, OnlyAFirstAttemptThatOthersMayHelpMayGiveUp) {
  ASSERT_TRUE(kGivesUp);
  const GridMap map = test::mapFromRows({".......", "@@@.@@@", "@@@.@@@"});
  Instance in;
  in.robots = {dot("A", {0, 0, 0}, {6, 0, 0}), dot("B", {6, 0, 1}, {0, 0, 1}), dot("C", {3, 1, 2}, {3, 1, 2})};
  asked.clear();
  const LayeredResult r = plan(map, in, "gives_up_test_backend", true, 10.0);
  ASSERT_TRUE(r.success()) << r.reason;
  EXPECT_TRUE(validatePlan(map, in, r.plan).valid());
  ASSERT_EQ(r.step_asides.size(), 1u);
  EXPECT_NE(r.step_asides[0].find("stuck"), std::string::npos) << r.step_asides[0];
  ASSERT_EQ(asked.size(), 3u);
  for (const Ask& a : asked) {
    const bool first_of_knot = a.robots == 2 && a.returning == 0;
    EXPECT_EQ(a.may_give_up, first_of_knot) << a.robots << " robots, " << a.returning << " returning";
  }
}

TEST(LayeredPlanner, RawModeIsOneSubproblem) {
  const GridMap map = test::freeMap(8, 4);
  Instance in;
  in.robots = {dot("a", {0, 0, 0}, {7, 0, 0}), dot("b", {0, 3, 0}, {7, 3, 0})};
  const LayeredResult r = plan(map, in, "la_cbs", /*layered=*/false);
  ASSERT_TRUE(r.success()) << r.reason;
  EXPECT_EQ(r.subproblems.size(), 1u);
  EXPECT_EQ(r.metrics.soc, 14);
}

// A decomposition whose largest subproblem holds at least whole_fleet_share of the robots (and
// whole_fleet_min_robots) is set aside: the fleet is one subproblem, the decomposition stays
// reported as computed, the answer says why, and the plan is valid.
TEST(LayeredPlanner, ADominantSubproblemMakesTheFleetOneSubproblem) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const GridMap map = randomMap(seed);
    const std::optional<Instance> fleet = test::randomFleet(map, 6, seed);
    if (!fleet) continue;
    const FleetGraphs graphs(map, footprintsOf(*fleet));
    LayeredOptions o;
    o.backend = "la_lns";
    o.budget.whole_fleet_share = 2.0;  // never
    const LayeredResult split = planLayered(map, *fleet, graphs, o, Deadline::in(5.0));
    if (!split.success() || split.decomposition.subproblems.size() < 2) continue;
    const int largest = split.decomposition.largest();
    EXPECT_TRUE(split.solved_as_one.empty());
    o.budget.whole_fleet_share = static_cast<double>(largest) / 6.0;
    o.budget.whole_fleet_min_robots = static_cast<std::size_t>(largest) + 1;  // one short: split
    EXPECT_EQ(planLayered(map, *fleet, graphs, o, Deadline::in(5.0)).subproblems.size(), split.subproblems.size());
    o.budget.whole_fleet_min_robots = static_cast<std::size_t>(largest);
    const LayeredResult one = planLayered(map, *fleet, graphs, o, Deadline::in(5.0));
    ASSERT_TRUE(one.success()) << "seed " << seed << ": " << one.reason;
    EXPECT_EQ(one.subproblems.size(), 1u);
    EXPECT_EQ(one.subproblems[0].robots.size(), 6u);
    EXPECT_EQ(one.decomposition.subproblems.size(), split.decomposition.subproblems.size());
    EXPECT_NE(one.solved_as_one.find(std::to_string(largest) + " of 6 robots"), std::string::npos)
        << one.solved_as_one;
    const ValidationResult v = validatePlan(map, *fleet, one.plan);
    EXPECT_TRUE(v.valid()) << "seed " << seed << ": " << v.violation.message;
    return;
  }
  FAIL() << "no seed gave a decomposed, solved fleet";
}

TEST(LayeredPlanner, UnreachableTargetIsInfeasibleInBothModes) {
  const GridMap map = test::mapFromRows({"..@..", "..@.."});
  Instance in;
  in.robots = {dot("a", {0, 0, 0}, {4, 0, 0}), dot("b", {0, 1, 0}, {1, 1, 0})};
  for (bool layered : {true, false}) {
    const LayeredResult r = plan(map, in, "la_lacam", layered);
    EXPECT_EQ(r.status, SolveStatus::Infeasible) << r.reason;
    EXPECT_NE(r.reason.find("'a'"), std::string::npos) << r.reason;
  }
}

TEST(LayeredPlanner, UnknownBackendThrows) {
  const GridMap map = test::freeMap(3, 1);
  Instance in;
  in.robots = {dot("a", {0, 0, 0}, {2, 0, 0})};
  EXPECT_THROW(plan(map, in, "nope"), InvalidInput);
}

}  // namespace
}  // namespace fleet_planner
