#pragma once
/// Low level of LA-LNS (la_lns.h): space-time A* for one agent that treats the other agents'
/// current paths as soft obstacles. A path costs its length plus `collision_cost` for every
/// step during which it collides with another agent (and for every agent it would collide with
/// while it holds its target afterwards); static footprints and the moving obstacles of other
/// subproblems stay hard. In the spirit of SIPPS, the low level of
///   Li, Chen, Harabor, Stuckey, Koenig. "MAPF-LNS2: Fast Repairing for Multi-Agent Path
///   Finding via Large Neighborhood Search." AAAI 2022,
/// with a weighted sum in place of its lexicographic order, so that a bounded search still
/// answers on large maps.
#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/solvers/search/soft_path_table.h"

namespace fleet_planner {

struct SoftSearchOptions {
  /// Cost of one colliding step, in steps of path length.
  int collision_cost = 16;
  /// Expansions before the search gives up (NodeLimit).
  long long max_expansions = 200'000;
  /// Weight of the heuristic (>= 1): nodes are ordered by cost so far + weight x the lower bound
  /// of the rest. Above 1 the search goes for the target rather than proving the cheapest path
  /// (whose cost may be up to `weight` times lower); a path that must wait or detour for the
  /// others is then found after far fewer expansions. 1: the cheapest path.
  double heuristic_weight = 1.0;
};

struct SoftSearchResult {
  enum class Outcome { Found, NoPath, Expired, NodeLimit };
  Outcome outcome = Outcome::NoPath;
  StatePath path;      ///< states at t = 0, 1, ..., ending at the target, held from then on
  int collisions = 0;  ///< colliding steps, plus agents met while holding the target
  long long expansions = 0;
};

/// Cheapest path of agent a from its start to its target under that cost (within the factor
/// heuristic_weight). The agent's own path in `soft` (if any) is ignored.
SoftSearchResult softPathSearch(const SearchSpace& space, int a, const SoftPathTable& soft,
                                const Deadline& deadline, const SoftSearchOptions& options = {});

}  // namespace fleet_planner
