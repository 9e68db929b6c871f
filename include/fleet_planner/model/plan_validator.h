#pragma once
/// The plan validator: an independent check of any plan against the LA-MAPF model, used by the
/// tests, the CLI and the planners before they return. It relies on the footprint
/// discretisation and the map only: no state graph, no solver code.
///
/// It checks, in time order: one non-empty path per robot, starting at the start and ending at
/// the target; every state's footprint on the map and obstacle-free; every step a legal action
/// whose swept cells are obstacle-free; and, for every pair of robots at every step, no vertex
/// conflict (footprints overlap) and no transfer conflict (swept cells overlap). A robot whose
/// path has ended stays at its target. The first violation is reported.
#include <string>
#include <vector>

#include "fleet_planner/model/action.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"

namespace fleet_planner {

struct Violation {
  enum class Kind {
    None,
    WrongPathCount,    ///< the plan does not have one path per robot
    EmptyPath,
    WrongStart,        ///< path[0] is not the robot's start
    WrongTarget,       ///< the last state is not the robot's target
    StateInObstacle,   ///< a footprint covers a blocked cell or leaves the map
    IllegalAction,     ///< two consecutive states are not one action apart
    SweepInObstacle,   ///< an action sweeps a blocked cell
    VertexConflict,    ///< two footprints overlap at one time step
    TransferConflict,  ///< two robots sweep a common cell during one step
  };
  Kind kind = Kind::None;
  int robot = -1;  ///< index into the instance's robots
  int other = -1;  ///< the second robot of a conflict
  int time = -1;   ///< the time step (for a step t -> t+1: t)
  std::string message;
};

struct ValidationResult {
  bool valid() const { return violation.kind == Violation::Kind::None; }
  Violation violation;
};

/// Checks `plan` for `instance` on `map` under `model`. Conflicts involving a robot are checked
/// from its Robot::conflicts_from on.
ValidationResult validatePlan(const GridMap& map, const Instance& instance, const Plan& plan,
                              const ActionModel& model = {});

/// Same, for a plan in which only the robots `changed` differ from one already valid (same map,
/// model, and the other robots' paths and Robots): only their paths, and only the conflicts that
/// involve one of them, are checked. A revision during the execution (execution/replanning.h)
/// is checked this way: every other pair is as it was. States and steps before `from` (done by
/// every robot) are not checked at all.
ValidationResult validatePlanChanges(const GridMap& map, const Instance& instance, const Plan& plan,
                                     const ActionModel& model, const std::vector<int>& changed, int from = 0);

/// "vertex conflict", "transfer conflict", ... (lower case, for messages).
const char* violationName(Violation::Kind kind);

}  // namespace fleet_planner
