#pragma once
/// Robots of other subproblems that may have to step aside for a subproblem (beyond the paper).
/// A subproblem sees the robots of earlier subproblems at their targets and those of later ones
/// at their starts, as static obstacles. The decomposition makes sure that each robot alone can
/// pass them, but not that the subproblem's robots can pass each other as well: two robots that
/// must swap in a corridor may need the pocket that a standing robot fills. Such a subproblem
/// is solved again with the standing robots near its robots' ways as robots of its own, planned
/// from and back to where they stand, and with those on the paths of a plan of its robots alone
/// among the static obstacles: the pocket two robots need to trade places may be filled by a
/// robot far from either one's shortest way.
#include <vector>

#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

/// The entries of `standing` whose footprint comes within `margin` cells of a shortest path
/// (in its own state graph, ignoring other robots) of one of `robots`: the `max_count` nearest
/// (ties: first in `standing`), in the order of `standing`.
std::vector<StaticFootprint> robotsInTheWay(const Instance& instance, const FleetGraphs& graphs,
                                            const std::vector<int>& robots,
                                            const std::vector<StaticFootprint>& standing, int margin,
                                            std::size_t max_count);

/// The entries of `standing` whose footprint meets a path of `paths` (robot robots[i] drives
/// paths[i]: its footprint at each pose and its sweep from each pose to the next), in the order
/// of `standing`.
std::vector<StaticFootprint> robotsOnPaths(const FleetGraphs& graphs, const std::vector<int>& robots,
                                           const std::vector<Path>& paths,
                                           const std::vector<StaticFootprint>& standing);

}  // namespace fleet_planner
