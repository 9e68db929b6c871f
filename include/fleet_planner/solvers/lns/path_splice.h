#pragma once
/// Local repair of one agent's path for LA-LNS (la_lns.h): the steps around one of its
/// collisions are replanned collision-free (safe_interval_search.h) between two states of the
/// path itself, and the rest of the path is kept as it is, step for step. When the piece is on
/// time, the agents the new path collides with are therefore a subset of the old path's
/// partners, with that collision gone; a late piece delays the rest until the path's own waits
/// make up for it. A robot that must wait a few steps for another one to pass, on a path of
/// hundreds of steps, is repaired without replanning the whole path: the searches that replan
/// whole paths around the others as soft obstacles run out of nodes there, on large maps, as
/// soon as the detour costs more than a few steps.
#include <functional>
#include <optional>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/solvers/search/soft_path_table.h"

namespace fleet_planner {

/// The steps at which agent a's path in `table` starts a run of colliding steps (with any
/// agent), in time order.
std::vector<int> collisionStarts(const SearchSpace& space, int a, const SoftPathTable& table);

struct SpliceResult {
  std::optional<StatePath> path;  ///< the repaired path, if a window worked
  /// The step of the old path at which the piece rejoins it (-1: the piece ends at the target,
  /// held), and how many steps later the new path is there (path[rejoin + delay] ==
  /// old[rejoin]). From there the new path follows the old one state by state, leaving out the
  /// first `delay` of the old path's waits, so that it is back on the old timing after them.
  int rejoin = -1;
  int delay = 0;
  long long expansions = 0;
};

/// Agent a's path in `table`, repaired around the run of colliding steps that starts at step t:
/// windows that open 2, 8, 32 and 128 steps before it and close 8, 32, 128 and 512 steps after
/// its end (or at the target, held for good, where that is sooner) are tried in turn until one
/// has a collision-free piece (at most `max_expansions` expansions each). With `delays`, a piece
/// may also rejoin the path later than it left it, by up to the steps the window closes after
/// the run: the rest of the path then keeps its moves but runs late until its own waits have
/// made up the delay, so it may meet other agents than before. With `keep`, a window whose
/// repaired path `keep` rejects counts as failed and the next one is tried: a wider window may
/// delay the rest of the path less, or not at all.
SpliceResult spliceAround(const SearchSpace& space, int a, const SoftPathTable& table, int t,
                          bool delays, const Deadline& deadline, long long max_expansions,
                          const std::function<bool(const StatePath&)>& keep = {});

}  // namespace fleet_planner
