#pragma once
/// A plan executed by simulated robots that are late at random: a check, in the core, that an
/// execution scheme keeps robots apart and brings each to its last state whatever the delays.
///
/// Time is continuous; things happen at discrete events (a robot finishes a step, and robots
/// start the steps now open to them). Each step takes its nominal duration (1) times a random
/// factor in [1, 1 + slowdown], plus, with stop_probability, a stop of up to max_stop nominal
/// steps; throughout it the robot covers the step's cells (PlanCells::during), at rest the
/// cells of its state (PlanCells::atRest). After every change, the robot that changed is
/// checked against every other robot, cell by cell.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fleet_planner/execution/plan_cells.h"
#include "fleet_planner/execution/step_dependencies.h"

namespace fleet_planner {

struct DelayModel {
  double slowdown = 1.0;          ///< a step takes [1, 1 + slowdown] nominal steps
  double stop_probability = 0.1;  ///< chance that a robot stops during a step
  double max_stop = 5.0;          ///< a stop lasts up to this many nominal steps
};

struct SimulationResult {
  enum class Outcome { Completed, Collision, Deadlock };
  Outcome outcome = Outcome::Completed;
  int robot = -1;          ///< Collision: the robot that changed; Deadlock: the first not done
  int other = -1;          ///< Collision: the robot it ran into
  double time = 0.0;       ///< when it happened; Completed: when the last robot arrived
  std::size_t events = 0;  ///< steps finished
  std::string message;     ///< what happened, for test messages
};

/// Executes the plan of `cells` with random delays drawn from `seed`. With `dependencies`, a
/// robot starts a step only when an ExecutionTracker releases it, and passes its waits without
/// stopping. Without (null), each robot runs its steps back to back, waits included: the plan's
/// own timing, stretched at random, as a robot with no coordination would drive it.
SimulationResult simulateExecution(const PlanCells& cells, const StepDependencies* dependencies,
                                   const DelayModel& delays, std::uint64_t seed);

/// "completed", "collision", "deadlock".
const char* outcomeName(SimulationResult::Outcome outcome);

}  // namespace fleet_planner
