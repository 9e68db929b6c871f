#pragma once
/// Planning some robots of an executing plan again while the others keep driving (issue: live
/// fleets): a robot blocked for long behind another that stopped, or one a user asks to re-plan,
/// gets a new way from the state it has reached to its target; nobody else's path changes.
///
/// One clock. The new plan keeps the executing plan's time steps: every other robot's path is
/// unchanged, and a re-planned robot keeps its path up to the state it has been released to
/// (where it stands, for a robot that waits; where it is bound, for one that drives) and
/// continues from there, at that state's time (several re-planned robots start together, at the
/// latest one's).
/// Its new steps are searched around the others' paths as timed moving obstacles from that time
/// on, so that the new plan is a valid plan (the validator checks it whole), and the dependencies
/// built from it (step_dependencies.h) order every pair of steps by that one clock: no cycle, so
/// no deadlock, and no collision at any timing, as for a fresh plan. Steps robots have done only
/// carry requirements that are met: the steps every robot has done are neither validated nor
/// looked at for dependencies again (from the smallest progress on), so that a re-plan's checks
/// do not grow with the plan's history (live goals lengthen it without end).
///
/// What is already released stays released. A robot may be anywhere on the steps it has been
/// released to (an executing robot drives them without asking again), so the search takes their
/// cells from now until the plan's time of each (MovingObstacle::held_through): the new steps
/// come after them in plan time, never before. The result is checked: a plan in which some other
/// robot would be released less far than it already is is refused.
///
/// Robots to keep away from. The robot a re-planned one was waiting for may stand still for a
/// long time (a fault, a person): its steps up to the state named in `avoid` are kept clear for
/// good (static obstacles), so the new way does not wait for it again.
///
/// New targets (live goals). A robot may get a new target, arrived or not. One that has arrived
/// at a yaw off the grid rests there: its path becomes that rest from step 0 until its new way
/// begins (Robot::start_turn), a history it did not drive but which only meets steps other
/// robots did before it arrived; conflicts of that history are not checked
/// (Robot::conflicts_from) and its requirements on them are met. Robots that have all arrived begin
/// their new ways no earlier than the slowest other robot's progress.
///
/// Robots moved off their paths (a push, a drift, a controller that erred). A robot may stand at
/// a pose no state of its plan has (`moved`): it is planned again from that pose. Its path
/// becomes a rest there from step 0 (a history it did not drive) until its new way begins, no
/// earlier than every other robot's progress, and its rewritten history is checked from the
/// slowest other robot's progress on (Robot::conflicts_from): steps everybody else has done are
/// the past, steps somebody has not done must not meet the robot where it stands. It resumes at
/// its rest (ReplanResult::progress). A re-plan in which some robot has still to pass where it
/// stands, before it can leave, is refused.
///
/// Connections. A re-planned robot's progress state may lie off its lattice (a start's or a
/// target's connecting motion): it is connected again, as planFleet does (lattice.h), and its
/// target's connection runs at the earliest step at which it meets nobody.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fleet_planner/execution/step_dependencies.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"
#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

/// Keep clear, for good, of `robot`'s states from its progress through `through`.
struct AvoidedSteps {
  int robot = -1;
  int through = 0;
};

/// A new target for a robot (its goal changes while the others drive).
struct NewTarget {
  int robot = -1;
  GridPose target;
  std::optional<double> target_yaw;
};

/// A robot that stands off its plan: at `pose` (its cell and nearest grid heading) and, when that
/// heading is not its yaw, at `yaw`.
struct MovedRobot {
  int robot = -1;
  GridPose pose;
  std::optional<double> yaw;
};

struct ReplanRequest {
  const GridMap* map = nullptr;
  const Instance* instance = nullptr;   ///< the executing plan's robots (targets as planned)
  const FleetGraphs* graphs = nullptr;  ///< their graphs on the plan's lattice (ActionModel::step)
  const Plan* plan = nullptr;           ///< the executing plan
  std::vector<int> progress;            ///< per robot: the state it has reached
  std::vector<int> released;            ///< per robot: the state it may already drive to (>= progress)
  std::vector<int> robots;              ///< to plan again (instance indices), from their releases
  std::vector<AvoidedSteps> avoid;
  std::vector<NewTarget> targets;  ///< robots given new targets (planned again too)
  std::vector<MovedRobot> moved;   ///< robots off their paths (planned again too, from there)
  std::string backend = "la_lns";  ///< a backend that avoids moving obstacles
  Deadline deadline;
  std::uint64_t seed = 0;
};

struct ReplanResult {
  SolveStatus status = SolveStatus::InvalidInput;
  std::string reason;  ///< names the robot where one is to blame
  /// On success: the executing plan with the re-planned robots' new paths (same clock), and its
  /// robots: the new targets, and, for a robot that rests at a yaw off the grid until its new way
  /// begins, that rest (Robot::start_yaw, start_turn).
  Plan plan;
  Instance instance;
  StepDependencies dependencies;  ///< of `plan`
  /// Per robot, the state of `plan` it resumes from: its progress, or a moved robot's rest.
  std::vector<int> progress;
  double time_s = 0.0;
  std::string stages;  ///< where the time went: "connect 0.004 s, search 0.120 s, ..."
  bool success() const { return status == SolveStatus::Success; }
};

/// Re-plans request.robots as described above. Never throws for planning outcomes: a request
/// that is malformed (sizes, indices, a progress off its path) is INVALID_INPUT with the reason.
/// Robots released to their last state are left as they are. Deterministic for a seed.
ReplanResult replanRobots(const ReplanRequest& request);

}  // namespace fleet_planner
