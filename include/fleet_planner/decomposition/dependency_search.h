#pragma once
/// search_path_agent and search_path_SAT (paper: "Variants of search path") over a robot's
/// component connectivity graph: a complete search for a path from the robot's start component
/// to its target component that enters only components whose SATs pass a filter, returning the
/// SATs the path is related to. Among paths it prefers those related to fewer SATs (Dijkstra,
/// a step into a component costing the SATs it adds to those of the component left), so that
/// robots depend on as few others as they can.
#include <optional>
#include <vector>

#include "fleet_planner/decomposition/relation_graph.h"

namespace fleet_planner {

/// Which SATs a path may touch: `allowed[sat]` nonzero (all when `allowed` is empty) and
/// `avoided[sat]` zero (none avoided when empty).
struct SatFilter {
  std::vector<char> allowed;
  std::vector<char> avoided;
  bool passes(int sat) const {
    return (allowed.empty() || allowed[sat]) && (avoided.empty() || !avoided[sat]);
  }
};

/// The SATs (ascending) of the best path through components that pass `filter`, or nullopt if
/// no such path exists.
std::optional<std::vector<int>> searchPathSats(const RelationGraph& graph, const SatFilter& filter);

/// Whether searchPathSats would find a path (`has_value()`), without ranking paths: a plain
/// graph search, for the queries that only ask whether a robot can avoid some SATs. When a path
/// exists and `witness` is given, it receives the SATs (ascending) of the path found: any filter
/// that passes all of them has a path too.
bool pathExists(const RelationGraph& graph, const SatFilter& filter, std::vector<int>* witness = nullptr);

}  // namespace fleet_planner
