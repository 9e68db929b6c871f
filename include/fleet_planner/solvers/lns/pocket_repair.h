#pragma once
/// A repair of LA-LNS (la_lns.h) for two agents that must trade places: one of them first drives
/// into a pocket off the other's way and waits there, the other drives to its target, and then
/// the first leaves the pocket for its own target. Each of the three legs is a collision-free
/// safe interval search (safe_interval_search.h) around every other agent's path, so the result
/// collides with nobody.
///
/// Two large robots in an aisle between shelves, each starting on the other's way, collide
/// whatever one of them does around the other's fixed path, and the ordered repair
/// (ordered_repair.h) fails in both orders: the second robot still stands where the first must
/// pass. A joint search of the pair finds the manoeuvre only after a search over joint states
/// that grows with the detour (LA-LaCAM needed 431,000 configurations for such a pair of
/// Huskies at lattice step 2). Here the pocket is searched instead: the parking robot's states
/// in breadth-first order from its start, kept when its footprint there meets neither the other
/// robot's shortest path nor any agent's final state, and spread at least half its radius apart.
#include <optional>
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/solvers/search/soft_path_table.h"

namespace fleet_planner {

struct PocketRepairOptions {
  int max_pockets = 8;              ///< pockets tried (each: up to three searches)
  long long max_states = 200'000;   ///< states of the breadth-first search for pockets
  /// Expansions of all the legs' safe interval searches together: a pocket that fails costs
  /// little where legs are short, and on long ways (mazes) the repair gives up early.
  long long max_expansions = 20'000;
};

/// Paths {through's, parks's} (neither agent in `table`): `parks` drives to a pocket and waits
/// there while `through` drives to its target along a path that `through_way` (its shortest
/// path, ignoring other agents) suggests keeping clear; then `parks` drives to its own target.
/// Both collide with no agent of `table` and not with each other. None if no pocket tried
/// works. `table` is used as scratch and is as it was on return; the expansions spent are added
/// to `expansions`. Deterministic.
std::optional<std::vector<StatePath>> pocketRepair(const SearchSpace& space, SoftPathTable& table,
                                                   int through, int parks,
                                                   const StatePath& through_way,
                                                   const Deadline& deadline,
                                                   const PocketRepairOptions& options,
                                                   long long& expansions);

}  // namespace fleet_planner
