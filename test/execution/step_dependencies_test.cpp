// Step dependencies (step_dependencies.h): exact lists on small hand-made plans, the same lists as
// the rule written the obvious way on random planned worlds, the same lists every time, and the
// cost on a large fleet.
#include "fleet_planner/execution/step_dependencies.h"

#include <gtest/gtest.h>

#include <chrono>
#include <iostream>

#include "execution_worlds.h"
#include "fleet_planner/execution/execution_tracker.h"

namespace fleet_planner::test {
namespace {

using Steps = std::vector<std::vector<Requirement>>;

struct Case {
  GridMap map;
  Instance instance;
  Plan plan;
};

Case twoDots(GridMap map, Robot a, Robot b, Path pa, Path pb) {
  Case c{std::move(map), {}, {}};
  c.instance.robots = {std::move(a), std::move(b)};
  c.plan.paths = {std::move(pa), std::move(pb)};
  const ValidationResult v = validatePlan(c.map, c.instance, c.plan);
  EXPECT_TRUE(v.valid()) << v.violation.message;
  return c;
}

TEST(StepDependencies, AFollowerEntersEachCellOnlyAfterTheLeaderHasLeftIt) {
  // A corridor of one row; b follows a to the right, one step behind (it waits at step 0).
  const Case c = twoDots(freeMap(5, 1), dot("a", {1, 0, 0}, {4, 0, 0}), dot("b", {0, 0, 0}, {3, 0, 0}),
                         {{1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}},
                         {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}});
  const StepDependencies deps = buildStepDependencies(c.instance, c.plan);
  EXPECT_EQ(deps.before[0], (Steps{{}, {}, {}}));  // a goes first: it needs nothing
  // b's move 1 enters cell 1, which a left in its step 0; move 2 enters cell 2, left in step 1...
  EXPECT_EQ(deps.before[1], (Steps{{}, {{0, 1}}, {{0, 2}}, {{0, 3}}}));
  EXPECT_EQ(deps.count(), 3u);
}

TEST(StepDependencies, ARobotWaitsForTheOtherToLeaveWhereItGoes) {
  // a crosses row 0; b, below the corridor, waits and then moves up into (2, 0) at step 3. a
  // passes (2, 0) in its steps 1 and 2: b needs a to be past the later one (at state 3).
  const Case c = twoDots(freeMap(5, 2), dot("a", {0, 0, 0}, {4, 0, 0}), dot("b", {2, 1, 3}, {2, 0, 3}),
                         {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}},
                         {{2, 1, 3}, {2, 1, 3}, {2, 1, 3}, {2, 1, 3}, {2, 0, 3}});
  const StepDependencies deps = buildStepDependencies(c.instance, c.plan);
  EXPECT_EQ(deps.before[0], (Steps{{}, {}, {}, {}}));
  EXPECT_EQ(deps.before[1], (Steps{{}, {}, {}, {{0, 3}}}));
}

TEST(StepDependencies, ARobotThatWaitsSeveralStepsOnAPlaceMustHaveLeftIt) {
  // b stands on (2, 0) for three steps, then moves down out of the corridor at step 3; a, from
  // (1, 0), enters (2, 0) at step 4. a needs b past its move (state 4), not merely past its
  // first wait there (state 1, which b reaches without moving: it passes waits at once).
  const Case c = twoDots(freeMap(5, 2), dot("a", {0, 0, 0}, {3, 0, 0}), dot("b", {2, 0, 2}, {2, 1, 2}),
                         {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}},
                         {{2, 0, 2}, {2, 0, 2}, {2, 0, 2}, {2, 0, 2}, {2, 1, 2}});
  const StepDependencies deps = buildStepDependencies(c.instance, c.plan);
  // a's step 5 touches (2, 0) too, which b's step 3 swept: already required at step 4, dropped.
  EXPECT_EQ(deps.before[0], (Steps{{}, {}, {}, {}, {{1, 4}}, {}}));
  EXPECT_EQ(deps.before[1], (Steps{{}, {}, {}, {}}));
}

TEST(StepDependencies, ATurnToATargetYawWaitsForWhoeverPassedThroughItsSweep) {
  // A bar 3 cells long rests at (2, 2) along +x and ends turning to 45 degrees (its last step),
  // which sweeps (3, 3); a dot passes (3, 3) and leaves it upwards at step 3. The turn is a
  // move with a requirement: the dot at state 4. As a wait it would need nothing.
  Robot bar = makeRobot("bar", Footprint::block(-1.4, -0.4, 1.4, 0.4), {2, 2, 0}, {2, 2, 0});
  bar.target_yaw = 0.785;
  Case c{freeMap(6, 5), {}, {}};
  c.instance.robots = {dot("d", {5, 3, 1}, {3, 4, 2}), bar};
  c.plan.paths = {{{5, 3, 1}, {4, 3, 1}, {3, 3, 1}, {3, 3, 2}, {3, 4, 2}},
                  Path(6, GridPose{2, 2, 0})};
  const ValidationResult v = validatePlan(c.map, c.instance, c.plan);
  ASSERT_TRUE(v.valid()) << v.violation.message;
  const PlanCells cells(c.instance, c.plan);
  EXPECT_FALSE(cells.isMove(1, 3));
  EXPECT_TRUE(cells.isMove(1, 4));
  const StepDependencies deps = buildStepDependencies(cells);
  EXPECT_EQ(deps.before[0], (Steps{{}, {}, {}, {}}));
  EXPECT_EQ(deps.before[1], (Steps{{}, {}, {}, {}, {{0, 4}}}));
}

TEST(StepDependencies, SameListsAsTheRuleWrittenDirectlyOnRandomPlans) {
  for (const PlannedWorld& w : testWorlds()) {
    const PlanCells cells(w.instance, w.plan, w.model);
    const StepDependencies deps = buildStepDependencies(cells);
    EXPECT_EQ(deps.before, referenceDependencies(cells).before) << w.name;
    EXPECT_EQ(buildStepDependencies(cells).before, deps.before) << w.name << ": not deterministic";
  }
  EXPECT_EQ(testWorlds().size(), 17u);
}

// From a state every robot has reached, the steps before it are not looked at: every execution
// tracked from there is released exactly as with the whole plan's dependencies.
TEST(StepDependencies, FromAStateEveryRobotHasReachedTheReleasesAreTheSame) {
  Rng rng(11);
  int compared = 0;
  for (const PlannedWorld& w : testWorlds()) {
    const PlanCells cells(w.instance, w.plan, w.model);
    const StepDependencies whole = buildStepDependencies(cells);
    int horizon = 0;
    for (int i = 0; i < cells.robots(); ++i) horizon = std::max(horizon, cells.lastState(i));
    for (int from : {1, horizon / 3, horizon / 2}) {
      const StepDependencies window = buildStepDependencies(PlanCells(w.instance, w.plan, w.model, from));
      EXPECT_LE(window.count(), whole.count()) << w.name;
      for (int trial = 0; trial < 20; ++trial) {
        std::vector<int> progress;
        for (int i = 0; i < cells.robots(); ++i) {
          const int last = cells.lastState(i);
          // Half of the robots stand exactly at `from`, the first state whose step is looked at.
          const int low = std::min(from, last);
          progress.push_back(rng.uniformInt(0, 1) ? low : static_cast<int>(rng.uniformInt(low, last)));
        }
        const ExecutionTracker a(w.plan, whole, progress), b(w.plan, window, progress);
        for (int i = 0; i < cells.robots(); ++i) {
          EXPECT_EQ(a.releasedUpTo(i), b.releasedUpTo(i)) << w.name << " from " << from << " robot " << i;
        }
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, 17 * 3 * 20);
}

// Random walks of many robots of mixed sizes on one open area: not a valid plan (robots cross
// freely), which is the hard case for the index (many robots on a cell), and a size no test
// world reaches.
Plan randomWalks(const Instance& instance, int steps, std::uint64_t seed) {
  Rng rng(seed);
  Plan plan;
  for (const Robot& r : instance.robots) {
    Path p = {r.start};
    while (static_cast<int>(p.size()) <= steps) {
      GridPose s = p.back();
      const auto roll = rng.uniformInt(0, 9);
      if (roll < 6) {
        s = applyAction(s, Action::Forward);
        if (s.x < 2 || s.y < 2 || s.x > 117 || s.y > 117) s = p.back();
      } else if (roll < 8) {
        s = applyAction(s, roll == 6 ? Action::RotateCcw : Action::RotateCw);
      }
      p.push_back(s);
    }
    plan.paths.push_back(p);
  }
  return plan;
}

TEST(StepDependencies, AHundredRobotsOfFiveHundredStepsInWellUnderASecond) {
  Instance instance;
  Rng rng(5);
  for (int i = 0; i < 100; ++i) {
    const GridPose start{static_cast<int>(rng.uniformInt(10, 110)), static_cast<int>(rng.uniformInt(10, 110)), 0};
    instance.robots.push_back(makeRobot(std::to_string(i),
                                        i % 2 ? Footprint::circle(0.4 + 0.1 * (i % 12))
                                              : Footprint::block(-1.0, -0.6, 1.2, 0.6),
                                        start, start));
  }
  const Plan plan = randomWalks(instance, 500, 5);
  for (std::size_t i = 0; i < plan.paths.size(); ++i) instance.robots[i].target = plan.paths[i].back();
  const auto t0 = std::chrono::steady_clock::now();
  const PlanCells cells(instance, plan);
  const StepDependencies deps = buildStepDependencies(cells);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "100 robots x 500 steps: " << deps.count() << " requirements in " << s << " s\n";
  EXPECT_GT(deps.count(), 100u);
  EXPECT_LT(s, 1.0);
}

}  // namespace
}  // namespace fleet_planner::test
