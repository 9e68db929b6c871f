#pragma once
/// Execution dependencies of a plan: which steps of other robots each step must wait for, so that
/// the plan can be executed with any delays, collision-free and deadlock-free.
///
/// References: W. Hönig, T. K. S. Kumar, L. Cohen, H. Ma, H. Xu, N. Ayanian, S. Koenig,
/// "Multi-Agent Path Finding with Kinematic Constraints", ICAPS 2016 (MAPF-POST: the temporal
/// plan graph, Section 4); W. Hönig, S. Kiesel, A. Tinka, J. W. Durham, N. Ayanian, "Persistent
/// and Robust Execution of MAPF Schedules in Warehouses", RA-L 4(2) 2019 (the action dependency
/// graph, Section III-B, type-2 edges). Here with footprints: "the same location" is "a common
/// cell" of the cells each robot covers (plan_cells.h).
///
/// Model. Robot i's path has states 0..L_i; step t moves it from state t to t + 1 (a wait when
/// both are the same pose). Its progress is the last state it has reached. During step t it
/// covers occ_i(t) = sweepAt(t) (both end bodies included; a wait or the rest after L_i: the
/// body). Robot i may START its move t only when, for every other robot j, progress_j >= T + 1,
/// where T is the LAST time T < t at which occ_j(T) shares a cell with occ_i(t): j must have left
/// every place that overlaps, not merely have started to leave (a j that waits over several
/// steps on such a place occupies it until its last one). Waits need nothing: a robot passes them
/// as soon as its next move is released. Requirements already implied by an earlier move of the
/// same robot (on the same j, at least as high) are dropped. For a valid plan T is always a move
/// of j, the one that leaves (its sweep holds its start body), never a wait on the place.
///
/// Why no collision at any timing, for a valid plan (validatePlan: no two robots share a cell in
/// the same step). Robot j's progress only grows. Take i doing move t and j doing step s (or at
/// rest at state k, sitting on body_j(k) from its last move w < k, or from state 0, until its
/// next move m >= k). If they shared a cell: s = t contradicts validity; s < t means i started t
/// only after j reached s + 1 (T >= s), so j cannot still be doing s; s > t is the same argument
/// with i and j swapped. At rest, body_j(k) lies in occ_j(T) for every T in [w, m] (sweeps hold
/// both end bodies): if t is in that range, validity is contradicted; if t > m, i's requirement
/// makes j's progress exceed m >= k; if t < w, j's move w required i's progress > t. Two robots at
/// rest are the same argument with their spans [w + 1, m]. Why no deadlock: every requirement of
/// step t names a state T + 1 <= t of another robot: once every robot has passed its waits (always
/// released), the robot whose next move m is earliest in plan time is released (each j stands at
/// a state >= m >= T + 1). Dependencies point strictly backwards in plan time: no cycle.
///
/// A plan that is not valid may yield requirements no robot can meet (a deadlock, never a
/// collision): validate first.
///
/// Cost. One pass in plan time over an index of the plan's cells: each cell keeps, per robot that
/// covered it, the last step it did so. A move looks up its own cells; every robot covering them
/// before it is found exactly (no broad phase needed, no pair of robots that never come close is
/// ever looked at). Waits and rests are indexed once per stretch, not per step. Time:
/// O(sum over moves and stretches of cells x robots per cell); memory: one int per cell of the
/// plan's bounding box plus one entry per (cell, robot) that ever covers it.
#include <cstddef>
#include <vector>

#include "fleet_planner/execution/plan_cells.h"
#include "fleet_planner/model/action.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"

namespace fleet_planner {

/// Robot `robot` must have reached state `state` (its progress >= state).
struct Requirement {
  int robot = -1;
  int state = 0;
  friend bool operator==(const Requirement& a, const Requirement& b) {
    return a.robot == b.robot && a.state == b.state;
  }
  friend bool operator!=(const Requirement& a, const Requirement& b) { return !(a == b); }
};

struct StepDependencies {
  /// before[i][t]: what robot i needs before it starts step t (t = 0 .. its last state - 1),
  /// sorted by robot, at most one per robot; empty for waits and for moves that need nothing.
  std::vector<std::vector<std::vector<Requirement>>> before;

  /// Number of requirements in all.
  std::size_t count() const;
};

/// The dependencies of `cells` (a valid plan's, see above). Deterministic. With cells.from() > 0
/// (every robot has reached that state), steps before it need nothing and what they covered is
/// not looked at: what it drops are requirements every robot already meets, so an execution
/// tracked from states >= from is released exactly as with the whole plan's dependencies, at a
/// cost that does not grow with the plan's history.
StepDependencies buildStepDependencies(const PlanCells& cells);

/// Same, building the cells of `plan` for `instance` under `model` (the plan's lattice step),
/// from step `from`. Throws InvalidInput like PlanCells.
StepDependencies buildStepDependencies(const Instance& instance, const Plan& plan, const ActionModel& model = {},
                                       int from = 0);

}  // namespace fleet_planner
