#pragma once
/// Breadth-first searches over one state graph (every action costs one step).
#include <cstdint>
#include <vector>

#include "fleet_planner/model/state_graph.h"

namespace fleet_planner {

/// Steps from every state to `target` (backward search); -1 where the target is unreachable.
/// Indexed by state id. The exact heuristic of the solvers' low-level searches.
std::vector<std::int32_t> distancesTo(const StateGraph& graph, StateId target);

/// Every state reachable from `start` (including it), in BFS order; empty if start is invalid.
std::vector<StateId> reachableFrom(const StateGraph& graph, StateId start);

/// True when `to` can be reached from `from` in the graph.
bool isReachable(const StateGraph& graph, StateId from, StateId to);

}  // namespace fleet_planner
