#pragma once
/// Searches over one state graph (every action costs one step): breadth-first, and one A*.
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

/// A lower bound on the steps from `from` to `to`: the moves a straight way along the axes needs
/// (a move advances the graph's step), and a quarter turn if the headings differ.
int stepsBound(const StateGraph& graph, const GridPose& from, const GridPose& to);

/// Steps from `from` to `to` (as distancesTo would count them) by A* with stepsBound, expanding
/// few states of a large graph; -1 if `to` is unreachable or not found within `max_expansions`
/// expansions. The expansions made are added to `expansions`. One search of a WaySearch made
/// for it (a cost table over the whole graph): for several searches on one graph, keep a
/// WaySearch.
int stepsBetween(const StateGraph& graph, StateId from, StateId to, long long max_expansions, long long& expansions);

/// stepsBetween, for many searches on one graph: the costs live in a table over the graph's
/// states, made once and reset where the last search wrote (a search per call would hash every
/// state it reaches, or clear a table of the whole graph).
class WaySearch {
 public:
  explicit WaySearch(const StateGraph& graph) : graph_(graph) {}
  int steps(StateId from, StateId to, long long max_expansions, long long& expansions);

 private:
  const StateGraph& graph_;
  std::vector<std::int32_t> cost_;  // -1: not reached; made on the first search
  std::vector<StateId> touched_;    // the entries of cost_ the last search set
};

}  // namespace fleet_planner
