#pragma once
/// Which robots of a packed subproblem must park before which (the parking plan's turns,
/// parking_plan.h). Robot a parks before robot b when a cannot get from its start to its target,
/// among the static obstacles, while b stands at its target: b's target closes a's only way in
/// or out, as at the mouth of a dead-end street where a's start or target lies deeper. If b
/// parks first, a has to push b off its target, and in such a street b has no pocket to go to.
/// The first parking order (parking_orders.h) puts such a robot after every robot it shuts in
/// or out.
///
/// A city has few such pairs: most robots can go round a parked robot, so unlike "a's shortest
/// way crosses b's target", which joins most of a city's robots into one cycle, the pairs form
/// an order. A cycle a -> b -> a means that neither can park first: the pair cannot both get
/// home (an INFEASIBLE pair); honourPrecedence then keeps the given order among them.
#include <vector>

#include "fleet_planner/solvers/search/agent_conflicts.h"
#include "fleet_planner/solvers/search/search_space.h"

namespace fleet_planner {

/// Whether agent a has a way from its start to its target that never overlaps agent b standing
/// at its target (only states checked, not the sweeps between them). Closed is decided when
/// either end's side of the way is exhausted: a search from the start (A* on a's distance
/// table) and one back from the target (breadth-first) take turns, so the small side (the
/// dead end) is exhausted within about its size. Unknown when the two searches together
/// expanded `max_expansions` states first.
enum class WayAround { Open, Closed, Unknown };
WayAround wayAroundTarget(const SearchSpace& space, int a, int b, long long max_expansions);

/// For each agent b, the agents a that must park before it: those whose shortest `ways` (one per
/// agent, as shortestWay) cross b's target and for which wayAroundTarget(a, b) is Closed.
std::vector<std::vector<int>> parkingPrecedence(const SearchSpace& space, const std::vector<StatePath>& ways,
                                                long long max_expansions_per_pair);

/// `order` changed as little as possible so that each agent comes after its `before` agents:
/// at each turn the earliest agent of `order` whose `before` agents all had their turns (Kahn's
/// algorithm by position in `order`); when none has (a cycle), the earliest agent left.
std::vector<int> honourPrecedence(const std::vector<int>& order, const std::vector<std::vector<int>>& before);

}  // namespace fleet_planner
