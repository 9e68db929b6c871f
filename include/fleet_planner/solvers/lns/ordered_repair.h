#pragma once
/// The cheap joint repair of LA-LNS (la_lns.h): a few agents replanned one after the other, in
/// a given order, each collision-free (safe_interval_search.h) around every other agent's path
/// and around the agents after it in the order standing at their starts. It is the layered
/// planner's rule (a later subproblem's robots wait at their starts) inside one knot: two
/// robots whose starts are side by side and whose ways share a corridor collide whatever each
/// does alone around the other's path, but one of them can keep out of the other's start and
/// the other then waits for it to pass. On maze-128-128-10 with 60 robots, the last colliding
/// pair of a 34-robot level is such a knot; neither one-by-one replanning around soft
/// obstacles nor LA-CBS within its budget unties it.
#include <optional>
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/solvers/search/soft_path_table.h"

namespace fleet_planner {

/// Paths for the agents of `order` (same order; none of them in `table`): agent order[i]'s is
/// its earliest-arriving path that collides with no agent of `table`, with no order[j] (j < i)
/// on its new path, and with no order[j] (j > i) standing at its start for good. Together they
/// collide with nobody. None if some agent has no such path within `max_expansions`
/// expansions or the deadline. `table` is used as scratch and is as it was on return; the
/// expansions spent are added to `expansions`.
std::optional<std::vector<StatePath>> orderedRepair(const SearchSpace& space, SoftPathTable& table,
                                                    const std::vector<int>& order,
                                                    const Deadline& deadline,
                                                    long long max_expansions,
                                                    long long& expansions);

}  // namespace fleet_planner
