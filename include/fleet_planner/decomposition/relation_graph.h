#pragma once
/// A robot's component connectivity graph G^c_i (paper: "Component connectivity graph").
///
/// SATs are the robots' starts and targets: SAT 2j is robot j's start, 2j + 1 its target. A
/// state is related to a SAT when the robot's footprint there, or the cells it sweeps rotating
/// out of it, overlap the SAT's footprint. This is the paper's r_s / r_t without the edge
/// clause for moves: a move sweeps only its two footprints, each already related on its own,
/// so a path through unrelated states still keeps clear of the SAT (the property legality
/// needs), while related regions are not dilated by one step. States are grouped into strongly
/// connected components of equal relations (edges between differently related states are
/// ignored); the components, each with its SATs, form the graph the dependency searches run on.
///
/// One component graph serves every robot with the same state graph: it is built from the
/// relations to all SATs, and each robot ignores its own two. Each component is still strongly
/// connected and uniformly related for that robot, so searches on this finer graph are exact.
#include <cstdint>
#include <memory>
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/instance.h"

namespace fleet_planner {

struct ComponentGraph {
  std::vector<std::int32_t> sat_begin{0};   ///< CSR: component -> its SATs (ascending)
  std::vector<std::int32_t> sats;
  std::vector<std::int32_t> edge_begin{0};  ///< CSR: component -> successor components
  std::vector<std::int32_t> edges;
  int numComponents() const { return static_cast<int>(sat_begin.size()) - 1; }
};

struct RelationGraph {
  std::shared_ptr<const ComponentGraph> graph;
  int robot = -1;   ///< whose graph: its own SATs are ignored
  int start = -1;   ///< component of the robot's start state
  int target = -1;  ///< component of the robot's target state
};

/// Builds every robot's relation graph, one component graph per distinct state graph, on up to
/// `threads` threads (same result for any count). The deadline is checked before each component
/// graph: once it has passed, no more are started and the robots left out get a null `graph`.
std::vector<RelationGraph> buildRelationGraphs(const Instance& instance, const FleetGraphs& graphs, int threads,
                                               const Deadline& deadline = {});

}  // namespace fleet_planner
