#pragma once
/// The end of a parking plan (parking_plan.h) that left robots short of their targets: once
/// every robot of the plan has stopped, those robots and the robots standing on their ways
/// home are planned together from where they stand, with everybody else standing still as a
/// static obstacle; their plan is appended to the parking plan.
///
/// The parking plan moves one robot at a time and gives up a robot whose way is blocked by
/// robots it cannot push (typically robots already home, deep in an aisle, with no pocket off
/// the way in reach). Repairing the whole subproblem softly around the parking plan's long
/// paths then costs seconds per robot left. The robots involved in such a knot are few, and
/// once the others have stopped they form a small static instance that a backend solves in
/// far less. The plan is long (they wait for everybody to stop): the layered planner's
/// retiming to the earliest schedule and its refinement shorten it.
#include <optional>
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/solvers/search/agent_conflicts.h"
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

struct LaLnsOptions;

struct EndGameOptions {
  /// Rounds of the group: the robots left and those standing on their ways home (each the way
  /// through fewest standing robots); then each round also the robots standing near those
  /// ways, within `margin` lattice steps after the first round, the margin doubling each round
  /// (8, 24, 56 steps in all), nearest first while the group holds fewer than `max_group`. A
  /// round that would add nobody is skipped: it would plan the same group again.
  int rounds = 4;
  int margin = 8;
  int max_group = 16;  ///< robots planned together at most: a first group beyond it ends the end game
};

/// Every agent's path (as `paths`, extended) with the agents not `home` at their targets; none
/// if no round found a plan before the deadline. `problem` is the subproblem `space` was made
/// from (without returning robots); the group is planned by LA-LNS with `lns` options (its own
/// end game off) within what is left of problem.max_expansions, `expansions` counting as
/// spent. The expansions spent are added to `expansions`.
std::optional<std::vector<StatePath>> endGame(const SearchSpace& space, const Subproblem& problem,
                                              const std::vector<StatePath>& paths,
                                              const std::vector<char>& home,
                                              const LaLnsOptions& lns, const Deadline& deadline,
                                              const EndGameOptions& options, long long& expansions);

}  // namespace fleet_planner
