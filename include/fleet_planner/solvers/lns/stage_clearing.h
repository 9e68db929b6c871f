#pragma once
/// A first plan of LA-LNS (la_lns.h) for a subproblem with returning robots (robots of other
/// subproblems that step aside: Subproblem::returning): the robots in the way clear the stage,
/// the others drive a plan made without them, and the robots in the way come back.
///
/// The layered planner frees the standing robots that block a failed subproblem (step_aside.h).
/// Two Huskies that must trade places in an aisle may need the pocket that a third robot fills:
/// that robot has to leave, wait while the two pass, and return, which no repair of one or two
/// robots at a time finds (the third robot's path is fine as long as it stays). Here:
///   1. `alone`: a plan of the other robots, made with the returning robots absent;
///   2. each returning robot whose footprint meets a cell of `alone` drives to a pocket off those
///      cells (pocket_repair.h), one after the other, the others waiting where they stand;
///   3. the other robots then follow `alone`, all delayed by the same number of steps;
///   4. the robots in pockets drive back to where they stood, the last to leave first.
/// Every leg is a collision-free safe interval search around everything planned so far, and the
/// delayed plan is checked against the parked robots, so the result collides with nobody.
#include <optional>
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/solvers/search/agent_conflicts.h"

namespace fleet_planner {

/// Paths for every agent of `space` (state ids at t = 0, 1, ...), or none if a step fails.
/// `returning[a]`: agent a is a returning robot (its start is its target). `alone[a]`: for the
/// other agents, their paths in a plan made without the returning robots (conflict-free among
/// themselves); ignored for returning agents. Pockets and leg searches are bounded by
/// `max_pockets` per robot and `max_expansions` in all; the expansions spent are added to
/// `expansions`. Deterministic.
std::optional<std::vector<StatePath>> clearTheStage(const SearchSpace& space, const std::vector<bool>& returning,
                                                    const std::vector<StatePath>& alone, const Deadline& deadline,
                                                    int max_pockets, long long max_expansions,
                                                    long long& expansions);

}  // namespace fleet_planner
