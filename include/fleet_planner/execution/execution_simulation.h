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
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fleet_planner/execution/execution_tracker.h"
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
  std::vector<double> arrivals;  ///< per robot: when it reached its last state (-1: never)
  std::string message;     ///< what happened, for test messages
};

/// A fault: `robot` starts no step from `from` until `until` (a person in the way).
struct Hold {
  int robot = -1;
  double from = 0.0;
  double until = 0.0;
};

/// A new plan handed over during the execution (replanning.h): the robots keep their progress
/// and the steps they are doing, which the new plan must keep, unless `progress` says otherwise.
struct SimulatedReplan {
  std::shared_ptr<const Instance> instance;
  std::shared_ptr<const Plan> plan;
  std::shared_ptr<const PlanCells> cells;  ///< of *plan for *instance
  StepDependencies dependencies;
  /// Where the robots stand in the new plan (ReplanResult::progress; empty: where they stood). A
  /// robot given another state stops there: a robot moved off its path, at its new rest.
  std::vector<int> progress;
};

/// The execution as a re-plan sees it, after each event.
struct ExecutionSnapshot {
  double time = 0.0;
  const PlanCells* cells = nullptr;
  const ExecutionTracker* tracker = nullptr;
  std::vector<bool> moving;  ///< per robot: doing its step from its progress
  std::vector<bool> held;    ///< per robot: held by a Hold now
};
using ReplanHook = std::function<std::optional<SimulatedReplan>(const ExecutionSnapshot&)>;

/// Executes the plan of `cells` with random delays drawn from `seed`. With `dependencies`, a
/// robot starts a step only when an ExecutionTracker releases it, and passes its waits without
/// stopping. Without (null), each robot runs its steps back to back, waits included: the plan's
/// own timing, stretched at random, as a robot with no coordination would drive it. `holds`
/// stop robots on purpose. With dependencies, `replan` is asked after every event whether to
/// switch to a new plan (collisions are then checked on the new plan's cells).
SimulationResult simulateExecution(const PlanCells& cells, const StepDependencies* dependencies,
                                   const DelayModel& delays, std::uint64_t seed,
                                   const std::vector<Hold>& holds = {}, const ReplanHook& replan = {});

/// "completed", "collision", "deadlock".
const char* outcomeName(SimulationResult::Outcome outcome);

}  // namespace fleet_planner
