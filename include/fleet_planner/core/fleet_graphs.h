#pragma once
/// The state graphs of a fleet on one map. Robots whose footprints cover the same cells in every
/// pose and sweep share one FootprintCells and one StateGraph (for example every circle of
/// radius 0.8 to 1.5 cells), so a fleet of 140 random robots needs only a few dozen graphs.
#include <memory>
#include <vector>

#include "fleet_planner/core/footprint.h"
#include "fleet_planner/core/grid_map.h"
#include "fleet_planner/core/obstacle_index.h"
#include "fleet_planner/core/state_graph.h"

namespace fleet_planner {

class FleetGraphs {
 public:
  /// Builds one graph per distinct discretised footprint, on up to `threads` threads (the result
  /// does not depend on the thread count). Throws InvalidInput for an unusable footprint.
  FleetGraphs(const GridMap& map, const std::vector<Footprint>& footprints, ActionModel model = {},
              int threads = 1);

  int numRobots() const { return static_cast<int>(robot_graph_.size()); }
  int numGraphs() const { return static_cast<int>(graphs_.size()); }
  const StateGraph& graph(int robot) const { return *graphs_[robot_graph_[robot]]; }
  const FootprintCells& cells(int robot) const { return graph(robot).cells(); }
  /// Index of the shared graph robot `robot` uses (robots with equal index share a graph).
  int graphIndex(int robot) const { return robot_graph_[robot]; }
  const ObstacleIndex& obstacles() const { return obstacles_; }
  /// Sum over robots of their graph's valid states.
  long long totalStates() const;
  std::size_t memoryBytes() const;

 private:
  ObstacleIndex obstacles_;
  std::vector<std::shared_ptr<const StateGraph>> graphs_;
  std::vector<int> robot_graph_;
};

}  // namespace fleet_planner
