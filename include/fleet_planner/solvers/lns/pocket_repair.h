#pragma once
/// A repair of LA-LNS (la_lns.h) for agents that must trade places: the others first drive into
/// pockets off one agent's way and wait there, that agent drives to its target, and then the
/// others leave their pockets for their own targets. Each leg is a collision-free safe interval
/// search (safe_interval_search.h) around every path planned so far, so the result collides
/// with nobody.
///
/// Two large robots in an aisle between shelves, each starting on the other's way, collide
/// whatever one of them does around the other's fixed path, and the ordered repair
/// (ordered_repair.h) fails in both orders: the second robot still stands where the first must
/// pass. A joint search of the pair finds the manoeuvre only after a search over joint states
/// that grows with the detour (LA-LaCAM needed 431,000 configurations for such a pair of
/// Huskies at lattice step 2). Here the pocket is searched instead (pocketsOffWay below). A third robot
/// whose target lies in the aisle waits in a pocket too, and arrives once the two have passed.
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
  /// The breadth-first search for pockets passes only through states clear of every agent's
  /// final state in the table (so that pockets behind standing robots are not offered).
  bool around_final_states = false;
  /// When fewer than max_pockets pockets are clear of the way, the last parker also tries
  /// states that cover some of it, the fewest cells first, where `through` can still drive
  /// past them (passesBeside): where the way runs along a corridor that holds the parker, the
  /// corridor may widen enough further on for the two to pass side by side.
  bool beside_way = false;
  /// Expansions of each passesBeside check (not counted in max_expansions).
  long long beside_expansions = 4'000;
};

/// Marks in `way` (a flag per map cell, sized to the map if empty) the cells agent a's footprint
/// covers along `path`: at each state and on the move to the next.
void markWay(const SearchSpace& space, int a, const StatePath& path, std::vector<char>& way);

/// Agent b's footprint at state s covers no cell marked in `way` (sized to the map).
bool clearOfWay(const SearchSpace& space, int b, StateId s, const std::vector<char>& way);

/// Pockets for agent b, the nearest first (at most options.max_pockets): states reachable from
/// `from` (its start if kNoState; breadth-first over its graph's edges, at most
/// options.max_states) from which it can reach its target, where its footprint covers no cell
/// marked in `way` and meets no agent's final state in `table`, spread half its radius apart.
/// With `beside`, when fewer pockets than that are found, also up to `count` of the states
/// reached that cover marked cells (and meet no final state), the fewest cells first, the
/// nearest first among equals. A filter only: static sweeps of the edges are left to the
/// searches that drive there.
std::vector<StateId> pocketsOffWay(const SearchSpace& space, int b, const SoftPathTable& table,
                                   const std::vector<char>& way, const PocketRepairOptions& options,
                                   StateId from = kNoState, std::vector<StateId>* beside = nullptr,
                                   std::size_t count = 0);

/// True when agent `through` can leave its way `way` (a path) where agent b's footprint at
/// state s meets it and join it again beyond, around that footprint alone: an A* over through's
/// graph from the way's states before the meeting (each at its step along the way) to any of
/// its states after it, within `max_expansions` expansions (added to `expansions`). False where the footprint meets the
/// way's first or last state, or no way round is found in time.
bool passesBeside(const SearchSpace& space, int through, const StatePath& way, int b, StateId s,
                  long long max_expansions, long long& expansions);

/// Paths {through's, then each parker's} (none of these agents in `table`): the parkers drive
/// to pockets off the way `through_way` (through's shortest path, ignoring other agents) and
/// wait there, one after the other, while `through` drives to its target; then the parkers
/// drive to their targets, in their order. Each parker but the last takes the first pocket it
/// reaches; the last tries its pockets in turn (with options.beside_way, then the states beside
/// the way that through passes). All collide with no agent of `table` and not
/// with each other. None if no pocket tried works. `table` is used as scratch and is as it was
/// on return; the expansions spent are added to `expansions`. Deterministic.
std::optional<std::vector<StatePath>> pocketRepair(const SearchSpace& space, SoftPathTable& table,
                                                   int through, const std::vector<int>& parkers,
                                                   const StatePath& through_way,
                                                   const Deadline& deadline,
                                                   const PocketRepairOptions& options,
                                                   long long& expansions);

}  // namespace fleet_planner
