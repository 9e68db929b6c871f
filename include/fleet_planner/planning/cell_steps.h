#pragma once
/// A lattice plan timed on the map's cells. On a lattice of step s one plan step moves a robot up
/// to s cells, so a step of that plan lasts as long as s steps of a plan on lattice step 1: at
/// the same speed a robot drives s cells, or it waits or turns and then stands the rest of
/// that time. The returned plan makes that explicit, one cell per step: every robot drives at
/// the speed of `seconds_per_step` per cell whatever the lattice, the plan's SOC and makespan
/// are in cell steps like a plan of lattice step 1, and the waits and turns that the lattice
/// made as long as a move can then be retimed on their own (execution/earliest_schedule.h).
///
/// Step t of a path (under `model`) becomes steps s*t .. s*t + s - 1: a move of k cells along
/// the heading is k moves of one cell followed by s - k waits; a rotation or a wait is that step
/// followed by s - 1 waits. The path's last step is not padded (a robot rests after its path;
/// a turn to a target yaw stays the path's last step, robot_cells.h). During each new step a
/// robot covers part of what it covered during the step it came from, at the same time, so a
/// plan valid under `model` is valid under the model of step 1.
#include "fleet_planner/model/action.h"
#include "fleet_planner/model/plan.h"

namespace fleet_planner {

/// `plan` (valid under `model`) on steps of one cell, as above; `plan` itself for model.step 1.
/// Throws InvalidInput for a step that is no motion under `model`.
Plan onCellSteps(const Plan& plan, const ActionModel& model);

}  // namespace fleet_planner
