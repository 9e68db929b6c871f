// Conformance of every LA-MAPF backend to the Solver contract (solver.h), on small hand-made
// maps ('.' free, '@' blocked, first row string = y 0). Every test that expects success checks
// the returned plan with the independent plan validator. Backend-specific behaviour (moving
// obstacles, optimality against the exhaustive reference search) follows the shared suite.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <string>
#include <vector>

#include "exhaustive_search.h"
#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/model/instance_check.h"
#include "fleet_planner/solvers/registry.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

/// a drives east along the corridor y = 0; b comes down the stem of the T at x = 3 and must
/// turn west. If b entered the corridor first the two would meet head-on in a 1-wide corridor,
/// so b has to wait in the stem until a has passed the junction.
World tJunction() {
  return World(mapFromRows({".......", "@@@.@@@", "@@@.@@@"}),
               {dot("a", {0, 0, 0}, {6, 0, 0}), dot("b", {3, 2, 3}, {0, 0, 1})});
}

/// The first `count` of six robots of every footprint kind (one-cell and 3 x 3 circles, a
/// forward and a sideways block, a triangle) crossing an open 12 x 12 map with a few obstacles.
/// Solvable for every count: with all six the robots can even go one at a time, the others
/// parked at start or target (e.g. in the order c1 p1 b1 b2 c2 c3, each on its single-robot
/// optimal route: a plan the validator accepts, SOC 380; checked offline), and dropping robots
/// from a valid plan leaves a valid plan. Four robots interact mildly.
World mixedFleet(std::size_t count) {
  std::vector<Robot> robots{
      dot("c1", {0, 1, 0}, {11, 10, 1}),
      makeRobot("c2", Footprint::circle(0.9), {2, 9, 3}, {9, 2, 2}),
      bar("b1", {8, 9, 1}, {3, 2, 0}),
      triangle("p1", {9, 5, 1}, {2, 6, 0}),
      dot("c3", {11, 1, 1}, {0, 10, 0}),
      makeRobot("b2", Footprint::block(-0.5, -0.5, 0.5, 1.5), {5, 9, 0}, {7, 3, 1})};
  robots.resize(count);
  return World(mapFromRows({"......@.....", "............", "............", "............",
                            "............", "@....@......", "......@....@", "............",
                            "............", "............", "............", ".....@......"}),
               robots);
}

class Conformance : public ::testing::TestWithParam<std::string> {};

/// Precondition of the success scenarios: the scenario passes the solvability pre-check.
::testing::AssertionResult wellFormed(const World& w) {
  const SolvabilityReport report = checkSolvability(w.instance, *w.graphs);
  if (report.solvable()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "test scenario is broken: " << report.summary();
}

TEST_P(Conformance, RegistryNameMatches) { EXPECT_EQ(makeSolver(GetParam())->name(), GetParam()); }

TEST_P(Conformance, RobotsAlreadyAtTargetsCostZero) {
  const World w(freeMap(8, 6), {dot("a", {1, 1, 0}, {1, 1, 0}), bar("b", {3, 1, 2}, {3, 1, 2}),
                                triangle("c", {6, 3, 1}, {6, 3, 1})});
  const Outcome o = solveWith(GetParam(), w, allRobots(w));
  ASSERT_TRUE(solvedValidly(o));
  EXPECT_EQ(o.soc, 0) << describe(o);
}

TEST_P(Conformance, RobotWaitsInTJunctionStemForCrossingRobot) {
  const World w = tJunction();
  ASSERT_TRUE(wellFormed(w));
  const Outcome o = solveWith(GetParam(), w, allRobots(w));
  EXPECT_TRUE(solvedValidly(o));
}

TEST_P(Conformance, HeadOnBlocksTurnToChangeLane) {
  // Both blocks stand in lane y = 2 facing each other. With no sideways or backward move, one
  // must turn 90 degrees, drive up into lane 3 and turn back to let the other pass. The hall is
  // just tall enough for the turn sweeps: with 5 rows the exhaustive search finds no plan.
  const World w(freeMap(10, 6),
                {bar("east", {1, 2, 0}, {7, 2, 0}), bar("west", {8, 2, 1}, {2, 2, 1})});
  ASSERT_TRUE(wellFormed(w));
  const Outcome o = solveWith(GetParam(), w, allRobots(w));
  ASSERT_TRUE(solvedValidly(o));
  bool turned = false;
  for (const Path& p : o.plan.paths)
    for (const GridPose& s : p) turned = turned || s.heading != p.front().heading;
  EXPECT_TRUE(turned) << "a valid plan here needs a rotation; " << describe(o);
}

TEST_P(Conformance, CorridorSwapUsesSidePocket) {
  const World w(mapFromRows({".......", "@@@.@@@"}),
                {dot("a", {0, 0, 0}, {6, 0, 0}), dot("b", {6, 0, 1}, {0, 0, 1})});
  ASSERT_TRUE(wellFormed(w));
  const Outcome o = solveWith(GetParam(), w, allRobots(w));
  ASSERT_TRUE(solvedValidly(o));
  bool pocket_used = false;
  for (const Path& p : o.plan.paths)
    for (const GridPose& s : p) pocket_used = pocket_used || (s.x == 3 && s.y == 1);
  EXPECT_TRUE(pocket_used) << describe(o);
}

TEST_P(Conformance, MixedFleetOfFourOnOpenMap) {
  const World w = mixedFleet(4);
  ASSERT_TRUE(wellFormed(w));
  const Outcome o = solveWith(GetParam(), w, allRobots(w));
  EXPECT_TRUE(solvedValidly(o));
}

// Solvable (robots moving one at a time give a valid plan, SOC 380). It pins LA-LaCAM's pushes
// that turn a blocker before it drives away, and its restarts out of dead ends.
TEST_P(Conformance, MixedFleetOfSixOnOpenMap) {
  if (GetParam() == "la_cbs") GTEST_SKIP() << "known weakness: LA-CBS times out on this instance (open)";
  const World w = mixedFleet(6);
  ASSERT_TRUE(wellFormed(w));
  const Outcome o = solveWith(GetParam(), w, allRobots(w));
  EXPECT_TRUE(solvedValidly(o));
}

TEST_P(Conformance, PathsFollowSubproblemRobotOrder) {
  const World w = mixedFleet(4);
  Subproblem sub = allRobots(w);
  sub.robots = {2, 0, 3, 1};
  const Outcome o = solveWith(GetParam(), w, sub);
  ASSERT_TRUE(solvedValidly(o));
  for (std::size_t k = 0; k < sub.robots.size(); ++k) {
    const Robot& r = w.instance.robots[sub.robots[k]];
    EXPECT_EQ(o.result.paths[k].front(), r.start) << "path " << k << " should be robot " << r.id;
    EXPECT_EQ(o.result.paths[k].back(), r.target) << "path " << k << " should be robot " << r.id;
  }
}

TEST_P(Conformance, CorridorSwapWithoutPocketFailsPromptly) {
  const World w(freeMap(6, 1), {dot("a", {0, 0, 0}, {5, 0, 0}), dot("b", {5, 0, 1}, {0, 0, 1})});
  const Outcome o = solveWith(GetParam(), w, allRobots(w, 1.0));
  EXPECT_TRUE(o.result.status == SolveStatus::Infeasible || o.result.status == SolveStatus::Timeout)
      << describe(o);
  EXPECT_LE(o.wall_s, 1.5) << describe(o);
}

TEST_P(Conformance, TightRoomHonoursShortDeadline) {
  // 8 dots cross an 8 x 8 room in reversed row order while 4 blocks in the middle trade
  // places diagonally, each ending turned round. There is no plan: blocks b0 and b2 touch each
  // other's footprint with every first move (the exhaustive search of the tests agrees), which
  // LA-LNS proves with its joint search; the others run out of time.
  std::vector<Robot> robots;
  for (int y = 0; y < 8; ++y)
    robots.push_back(dot("d" + std::to_string(y), {0, y, 0}, {7, 7 - y, 0}));
  const GridPose blocks[4] = {{2, 2, 0}, {2, 5, 0}, {5, 2, 1}, {5, 5, 1}};
  for (int k = 0; k < 4; ++k)
    robots.push_back(bar("b" + std::to_string(k), blocks[k], blocks[3 - k]));
  const World w(freeMap(8, 8), robots);
  ASSERT_TRUE(wellFormed(w));
  const Outcome o = solveWith(GetParam(), w, allRobots(w, 0.2));
  EXPECT_LE(o.wall_s, 0.25 + 0.1) << describe(o);
  if (o.result.status == SolveStatus::Success) {
    EXPECT_TRUE(solvedValidly(o));
  } else {
    EXPECT_TRUE(o.result.status == SolveStatus::Timeout || o.result.status == SolveStatus::Infeasible)
        << describe(o);
  }
}

TEST_P(Conformance, SameSubproblemAndSeedGiveSamePaths) {
  const World w = mixedFleet(4);
  const std::unique_ptr<Solver> solver = makeSolver(GetParam());
  const Outcome first = solveWith(*solver, w, allRobots(w, 10.0, 42));
  const Outcome again = solveWith(*solver, w, allRobots(w, 10.0, 42));
  const Outcome fresh = solveWith(GetParam(), w, allRobots(w, 10.0, 42));
  ASSERT_TRUE(solvedValidly(first));
  EXPECT_EQ(again.result.status, first.result.status) << describe(again);
  EXPECT_EQ(fresh.result.status, first.result.status) << describe(fresh);
  EXPECT_TRUE(again.result.paths == first.result.paths) << "same solver, second solve differs";
  EXPECT_TRUE(fresh.result.paths == first.result.paths) << "fresh solver differs";
}

TEST_P(Conformance, StaticFootprintForcesDetour) {
  // The parked block (instance robot 1, whose own start is elsewhere) stands at (3, 1) facing +y,
  // covering (3, 1) and (3, 2) on the runner's straight route along y = 1.
  const World w(freeMap(7, 4),
                {dot("runner", {0, 1, 0}, {6, 1, 0}), bar("parked", {0, 3, 0}, {0, 3, 0})});
  Subproblem sub = allRobots(w);
  sub.robots = {0};
  sub.blocked = {{1, {3, 1, 2}}};
  const Outcome o = solveWith(GetParam(), w, sub);
  ASSERT_TRUE(solvedValidly(o));
  EXPECT_EQ(staticFootprintClash(w, sub, o), "");
  EXPECT_GT(o.soc, 6) << "the straight route (cost 6) runs through the parked block; "
                      << describe(o);
}

TEST_P(Conformance, ReturningRobotStepsAsideAndComesBack) {
  // The helper stands in the corridor at (3, 0), away from its own start and target (3, 2): it
  // is planned from and back to that pose, and has to wait in the pocket while the runner passes.
  const World w(mapFromRows({".......", "@@@.@@@", "@@@.@@@"}),
                {dot("runner", {0, 0, 0}, {6, 0, 0}), dot("helper", {3, 2, 0}, {3, 2, 0})});
  Subproblem sub = allRobots(w);
  sub.returning = {{1, {3, 0, 0}}};
  const Outcome o = solveWith(GetParam(), w, sub);
  ASSERT_TRUE(solvedValidly(o));
  const Path& helper = o.plan.paths[1];
  EXPECT_EQ(helper.front(), (GridPose{3, 0, 0})) << describe(o);
  EXPECT_EQ(helper.back(), (GridPose{3, 0, 0})) << describe(o);
  bool pocket_used = false;
  for (const GridPose& s : helper) pocket_used = pocket_used || (s.x == 3 && s.y == 1);
  EXPECT_TRUE(pocket_used) << describe(o);
}

TEST_P(Conformance, ExpiredDeadlineTimesOut) {
  const World w = tJunction();
  Subproblem sub = allRobots(w);
  sub.deadline = Deadline::in(0.0);
  const Outcome o = solveWith(GetParam(), w, sub);
  EXPECT_EQ(o.result.status, SolveStatus::Timeout) << describe(o);
  EXPECT_LE(o.wall_s, 0.15) << describe(o);
}

TEST_P(Conformance, SetCancelFlagCancels) {
  const World w = tJunction();
  std::atomic<bool> cancel{true};
  Subproblem sub = allRobots(w);
  sub.deadline = Deadline::in(10.0, &cancel);
  const Outcome o = solveWith(GetParam(), w, sub);
  EXPECT_EQ(o.result.status, SolveStatus::Cancelled) << describe(o);
  EXPECT_LE(o.wall_s, 0.15) << describe(o);
}

TEST_P(Conformance, UnreachableTargetIsInfeasibleAndNamesRobot) {
  // The wall at x = 4 cuts the map in two; stranded_7's target lies on the other side.
  const World w(mapFromRows({"....@..", "....@..", "....@.."}),
                {dot("free_1", {0, 0, 0}, {2, 0, 0}), dot("stranded_7", {0, 2, 0}, {6, 2, 0})});
  const Outcome o = solveWith(GetParam(), w, allRobots(w, 2.0));
  EXPECT_EQ(o.result.status, SolveStatus::Infeasible) << describe(o);
  EXPECT_NE(o.result.reason.find("stranded_7"), std::string::npos) << describe(o);
}

INSTANTIATE_TEST_SUITE_P(Backends, Conformance, ::testing::Values("la_cbs", "la_lacam", "la_lns"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

// ---------------------------------------------------------------------------------------------
// The harness itself: a scripted backend shows that broken answers are caught.

/// Returns a fixed result, whatever the subproblem.
class ScriptedSolver : public Solver {
 public:
  explicit ScriptedSolver(std::vector<Path> paths) {
    result_.status = SolveStatus::Success;
    result_.paths = std::move(paths);
  }
  std::string name() const override { return "scripted"; }
  bool avoidsMovingObstacles() const override { return false; }
  SolveResult solve(const Subproblem&) override { return result_; }

 private:
  SolveResult result_;
};

TEST(SolverHarness, CatchesConflictsMisorderedPathsAndStaticClashes) {
  const World w(freeMap(4, 2), {dot("a", {0, 0, 0}, {1, 0, 0}), dot("b", {2, 0, 1}, {1, 0, 1})});
  const Path a{{0, 0, 0}, {1, 0, 0}}, b{{2, 0, 1}, {1, 0, 1}};
  ScriptedSolver both({a, b});  // both end on (1, 0) at t = 1
  const Outcome conflict = solveWith(both, w, allRobots(w));
  EXPECT_FALSE(solvedValidly(conflict));
  EXPECT_NE(describe(conflict).find("vertex conflict"), std::string::npos) << describe(conflict);
  ScriptedSolver swapped({b, a});
  EXPECT_NE(describe(solveWith(swapped, w, allRobots(w))).find("wrong start"), std::string::npos);
  ScriptedSolver short_answer({a});
  EXPECT_NE(describe(solveWith(short_answer, w, allRobots(w))).find("1 paths for 2"),
            std::string::npos);
  // Only a planned, next to b's footprint held static at (2, 0): fine; at (1, 0): a clash.
  Subproblem sub = allRobots(w);
  sub.robots = {0};
  ScriptedSolver only_a({a});
  sub.blocked = {{1, {2, 0, 1}}};
  const Outcome beside = solveWith(only_a, w, sub);
  EXPECT_TRUE(solvedValidly(beside));
  EXPECT_EQ(staticFootprintClash(w, sub, beside), "");
  sub.blocked = {{1, {1, 0, 1}}};
  EXPECT_NE(staticFootprintClash(w, sub, solveWith(only_a, w, sub)), "");
}

// ---------------------------------------------------------------------------------------------
// Registry.

TEST(SolverRegistry, ListsBothBackendsSorted) {
  const std::vector<std::string> names = solverNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "la_cbs"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "la_lacam"), names.end());
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
}

TEST(SolverRegistry, UnknownNameThrowsListingKnownNames) {
  try {
    makeSolver("nope");
    FAIL() << "makeSolver(\"nope\") did not throw";
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("nope"), std::string::npos) << what;
    EXPECT_NE(what.find("la_cbs"), std::string::npos) << what;
    EXPECT_NE(what.find("la_lacam"), std::string::npos) << what;
  }
}

// ---------------------------------------------------------------------------------------------
// la_cbs: serial backend, avoids moving obstacles, SOC-optimal.

TEST(LaCbs, AvoidsMovingObstacleCrossingItsRoute) {
  // A plus-shaped crossing. The mover drives north through (2, 2) at t = 2, exactly when the
  // runner, driving east, would be there on its straight route.
  const Path mover_path{{2, 0, 2}, {2, 1, 2}, {2, 2, 2}, {2, 3, 2}, {2, 4, 2}};
  const World w(
      mapFromRows({"@@.@@", "@@.@@", ".....", "@@.@@", "@@.@@"}),
      {dot("runner", {0, 2, 0}, {4, 2, 0}), dot("mover", mover_path.front(), mover_path.back())});
  const std::unique_ptr<Solver> solver = makeSolver("la_cbs");
  EXPECT_TRUE(solver->avoidsMovingObstacles());
  Subproblem sub = allRobots(w);
  sub.robots = {0};
  sub.moving = {{1, mover_path}};
  const Outcome o = solveWith(*solver, w, sub);
  ASSERT_TRUE(solvedValidly(o));
  // Both robots in one plan: the validator then checks runner against mover at every step.
  Plan joint;
  joint.paths = {o.result.paths[0], mover_path};
  const ValidationResult v = validatePlan(w.map, w.instance, joint);
  EXPECT_TRUE(v.valid()) << v.violation.message;
}

TEST(LaCbs, MovingObstacleStaysAtItsLastPose) {
  // The mover's path ends at t = 1 on (2, 1), on the runner's straight route along y = 1, and it
  // stays there forever: the runner must detour through row 0 or 2.
  const Path mover_path{{2, 0, 2}, {2, 1, 2}};
  const World w(freeMap(5, 3), {dot("runner", {0, 1, 0}, {4, 1, 0}),
                                dot("mover", mover_path.front(), mover_path.back())});
  Subproblem sub = allRobots(w);
  sub.robots = {0};
  sub.moving = {{1, mover_path}};
  const Outcome o = solveWith("la_cbs", w, sub);
  ASSERT_TRUE(solvedValidly(o));
  Plan joint;
  joint.paths = {o.result.paths[0], mover_path};
  const ValidationResult v = validatePlan(w.map, w.instance, joint);
  EXPECT_TRUE(v.valid()) << v.violation.message;
}

/// Tiny instances (2-3 robots, maps up to 5 x 4) for the optimality test.
struct TinyCase {
  const char* name;
  std::vector<std::string> rows;
  std::vector<Robot> robots;
};

std::vector<TinyCase> tinyCases() {
  return {
      {"wait_at_junction",
       {".....", "....."},
       {dot("a", {0, 0, 0}, {4, 0, 0}), dot("b", {2, 1, 3}, {2, 0, 3})}},
      {"step_aside_into_pocket",
       {"...", "@.@"},
       {dot("a", {1, 0, 2}, {1, 0, 2}), dot("b", {0, 0, 0}, {2, 0, 0})}},
      {"swap_via_pocket",
       {".....", "@@.@@"},
       {dot("a", {0, 0, 0}, {4, 0, 0}), dot("b", {4, 0, 1}, {0, 0, 1})}},
      {"block_turn_needs_dot_to_move",
       {".....", ".....", ".....", "....."},
       {bar("b", {1, 1, 0}, {1, 1, 2}), dot("c", {3, 1, 0}, {3, 1, 0})}},
      {"block_turns_into_block_lane",
       {".....", ".....", ".....", "....."},
       {bar("w", {4, 0, 1}, {2, 0, 1}), bar("n", {1, 1, 2}, {1, 1, 1})}},
      {"three_dots_rotate_round_ring",
       {"...", ".@.", "..."},
       {dot("a", {0, 0, 0}, {2, 0, 0}), dot("b", {2, 0, 2}, {2, 2, 2}),
        dot("c", {2, 2, 1}, {0, 2, 1})}},
      {"cross_robot_parked_on_its_target",
       {".....", "....."},
       {dot("a", {1, 0, 0}, {2, 0, 0}), dot("b", {0, 0, 0}, {4, 0, 0})}},
      {"block_and_two_dots",
       {".....", ".@...", ".....", "....."},
       {bar("w", {4, 2, 1}, {2, 2, 1}), dot("c", {1, 2, 3}, {4, 2, 0}),
        dot("d", {1, 3, 3}, {2, 3, 1})}},
  };
}

TEST(LaCbs, SocEqualsExhaustiveOptimumOnTinyInstances) {
  for (const TinyCase& c : tinyCases()) {
    SCOPED_TRACE(c.name);
    const World w(mapFromRows(c.rows), c.robots);
    const ExhaustiveResult best = exhaustiveSearch(w.map, w.instance);
    ASSERT_FALSE(best.budget_exhausted) << "reference search ran out of budget";
    ASSERT_GE(best.soc, 0) << "test case has no solution";
    const Outcome o = solveWith("la_cbs", w, allRobots(w, 20.0));
    ASSERT_TRUE(solvedValidly(o));
    EXPECT_EQ(o.soc, best.soc) << describe(o);
  }
}

// ---------------------------------------------------------------------------------------------
// la_lacam: parallel backend, static footprints only.

TEST(LaLacam, RejectsMovingObstacles) {
  const World w(freeMap(5, 3), {dot("a", {0, 1, 0}, {4, 1, 0}), dot("m", {2, 0, 2}, {2, 2, 2})});
  const std::unique_ptr<Solver> solver = makeSolver("la_lacam");
  EXPECT_FALSE(solver->avoidsMovingObstacles());
  Subproblem sub = allRobots(w);
  sub.robots = {0};
  sub.moving = {{1, {{2, 0, 2}, {2, 1, 2}, {2, 2, 2}}}};
  const Outcome o = solveWith(*solver, w, sub);
  EXPECT_EQ(o.result.status, SolveStatus::InvalidInput) << describe(o);
}

}  // namespace
}  // namespace fleet_planner::test
