#pragma once
/// What every backend does around its search: check the subproblem, build the search space,
/// answer trivial cases, time the call, and turn state-id paths into poses.
#include <functional>

#include "fleet_planner/solvers/search/agent_conflicts.h"
#include "fleet_planner/solvers/search/search_space.h"
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

/// Runs `search` on the subproblem's search space and fills in the time. Returns INVALID_INPUT
/// for a malformed subproblem (or moving obstacles given to a backend that cannot take them),
/// INFEASIBLE naming the robot when the pre-check fails (invalid or unreachable start or
/// target), TIMEOUT / CANCELLED when the deadline has already passed, SUCCESS with no paths for
/// an empty subproblem. Never throws.
SolveResult solveWith(const Subproblem& problem, bool moving_allowed,
                      const std::function<SolveResult(const SearchSpace&, SolveStats&)>& search);

/// A result with that status and reason (no paths).
SolveResult failedResult(SolveStatus status, std::string reason);

/// Paths of state ids as poses, trailing waits at the end trimmed.
std::vector<Path> toPosePaths(const SearchSpace& space, const std::vector<StatePath>& paths);

/// Pose paths of the given agents (paths[k] of agents[k]) as state ids of their graphs.
std::vector<StatePath> toStatePaths(const SearchSpace& space, const std::vector<int>& agents,
                                    const std::vector<Path>& paths);

}  // namespace fleet_planner
