#pragma once
/// ECBS's primal step (la_cbs.h): one agent planned around every other agent's path as hard
/// obstacles. Where a pair of robots keeps conflicting because each must give way to the other
/// for many steps, the constraint tree pays each step of the wait with a split; one robot
/// planned around the other's whole path (and everybody else's) gives a conflict-free plan at
/// once, which the tree keeps as its incumbent until its lower bound proves it good enough.
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/solvers/search/agent_conflicts.h"
#include "fleet_planner/solvers/search/search_space.h"
#include "fleet_planner/solvers/search/space_time_astar.h"

namespace fleet_planner {

/// The cheapest path of agent `a` from its start to its target whose footprint and sweeps
/// share no cell with any other agent's at the same step in `paths` (an agent holds the end of
/// its path for good; empty paths are ignored), by space-time A* (space_time_astar.h) with at
/// most `max_nodes` nodes.
LowLevelResult pathAroundOthers(const SearchSpace& space, int a, const std::vector<StatePath>& paths,
                                const Deadline& deadline, long long max_nodes);

/// `paths` made free of conflicts by planning agents around all the others in turn (each by
/// pathAroundOthers): of the first conflicting pair, the one whose path around the others adds
/// fewer steps to its own. That agent then meets nobody, so the agents in conflict fall by at
/// least one a turn. Empty if neither agent of a pair has such a path. The searches' expansions
/// are added to `expansions`.
std::vector<StatePath> aroundOthersInTurn(const SearchSpace& space, std::vector<StatePath> paths,
                                          const Deadline& deadline, long long max_nodes, long long& expansions);

}  // namespace fleet_planner
