// Plans executed with random delays and stops (execution_simulation.h): through their step
// dependencies, no two robots ever share a cell and every robot arrives; driven on the plan's
// timing alone, the same delays make robots collide (the check can fail).
#include "fleet_planner/execution/execution_simulation.h"

#include <gtest/gtest.h>

#include <iostream>

#include "execution_worlds.h"

namespace fleet_planner::test {
namespace {

const std::vector<PlannedWorld>& worlds() { return testWorlds(); }

DelayModel harsh() {
  DelayModel d;
  d.slowdown = 2.0;
  d.stop_probability = 0.15;
  d.max_stop = 6.0;
  return d;
}

TEST(DelayedExecution, TheRandomWorldsArePlannedAndValid) {
  int lattice = 0, yaws = 0;
  for (const PlannedWorld& w : worlds()) {
    EXPECT_TRUE(validatePlan(w.map, w.instance, w.plan, w.model).valid()) << w.name;
    lattice += w.model.step > 1;
    for (const Robot& r : w.instance.robots) yaws += r.start_yaw.has_value() + r.target_yaw.has_value();
  }
  EXPECT_EQ(worlds().size(), 17u);
  EXPECT_GE(lattice, 2);
  EXPECT_GE(yaws, 10);
}

TEST(DelayedExecution, ThroughTheDependenciesNoCollisionAndEveryRobotArrives) {
  int runs = 0;
  for (const PlannedWorld& w : worlds()) {
    const PlanCells cells(w.instance, w.plan, w.model);
    const StepDependencies deps = buildStepDependencies(cells);
    std::size_t steps = 0;
    for (int i = 0; i < cells.robots(); ++i) steps += cells.lastState(i);
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
      const SimulationResult r = simulateExecution(cells, &deps, harsh(), seed);
      ASSERT_EQ(r.outcome, SimulationResult::Outcome::Completed) << w.name << " seed " << seed << ": " << r.message;
      // Waits are passed without an event: the moves, each exactly once.
      std::size_t moves = 0;
      for (int i = 0; i < cells.robots(); ++i)
        for (int t = 0; t < cells.lastState(i); ++t) moves += cells.isMove(i, t);
      EXPECT_EQ(r.events, moves) << w.name;
      ++runs;
    }
  }
  EXPECT_EQ(runs, 17 * 40);
}

TEST(DelayedExecution, OnThePlansTimingAloneTheSameDelaysMakeRobotsCollide) {
  int collisions = 0, runs = 0;
  for (const PlannedWorld& w : worlds()) {
    const PlanCells cells(w.instance, w.plan, w.model);
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
      const SimulationResult r = simulateExecution(cells, nullptr, harsh(), seed);
      EXPECT_NE(r.outcome, SimulationResult::Outcome::Deadlock) << w.name;  // nobody waits for anybody
      collisions += r.outcome == SimulationResult::Outcome::Collision;
      ++runs;
    }
  }
  std::cout << "without dependencies: " << collisions << " of " << runs << " runs collide\n";
  EXPECT_GT(collisions, runs / 10);
}

TEST(DelayedExecution, WithoutDelaysBothWaysFollowThePlan) {
  DelayModel none;
  none.slowdown = 0.0;
  none.stop_probability = 0.0;
  for (const PlannedWorld& w : worlds()) {
    const PlanCells cells(w.instance, w.plan, w.model);
    const StepDependencies deps = buildStepDependencies(cells);
    const SimulationResult timed = simulateExecution(cells, nullptr, none, 1);
    EXPECT_EQ(timed.outcome, SimulationResult::Outcome::Completed) << w.name << ": " << timed.message;
    const SimulationResult released = simulateExecution(cells, &deps, none, 1);
    EXPECT_EQ(released.outcome, SimulationResult::Outcome::Completed) << w.name << ": " << released.message;
    EXPECT_LE(released.time, timed.time) << w.name << ": passing waits never makes the fleet later";
  }
}

TEST(DelayedExecution, SameSeedSameRun) {
  const PlannedWorld& w = worlds().front();
  const PlanCells cells(w.instance, w.plan, w.model);
  const StepDependencies deps = buildStepDependencies(cells);
  const SimulationResult a = simulateExecution(cells, &deps, harsh(), 9);
  const SimulationResult b = simulateExecution(cells, &deps, harsh(), 9);
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.events, b.events);
  EXPECT_NE(simulateExecution(cells, &deps, harsh(), 10).time, a.time);
}

}  // namespace
}  // namespace fleet_planner::test
