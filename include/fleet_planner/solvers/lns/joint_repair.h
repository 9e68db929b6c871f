#pragma once
/// The joint repair step of LA-LNS (la_lns.h): a few agents of a subproblem replanned together by
/// LA-CBS, every other agent's current path a moving obstacle. It unties the knots that
/// replanning one robot at a time cannot: two robots that must trade places through a pocket,
/// where each one's best answer to the other's straight path is to collide once.
#include <cstdint>
#include <vector>

#include "fleet_planner/solvers/search/soft_path_table.h"

namespace fleet_planner {

/// New collision-free paths for the agents of `group` (same order), around the paths in `table`
/// of every agent not in the group (group members must not be in the table), the subproblem's
/// static footprints and its moving obstacles; empty if LA-CBS found none within `seconds` and
/// `max_expansions`. Adds the expansions spent to `expansions`.
std::vector<StatePath> jointRepair(const SearchSpace& space, const Subproblem& problem,
                                   const SoftPathTable& table, const std::vector<int>& group,
                                   double seconds, long long max_expansions, std::uint64_t seed,
                                   long long& expansions);

}  // namespace fleet_planner
