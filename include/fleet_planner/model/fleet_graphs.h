#pragma once
/// The state graphs of a fleet on one map. Robots whose footprints cover the same cells in every
/// pose and sweep share one FootprintCells and one StateGraph (for example every circle of
/// radius 0.8 to 1.5 cells), so a fleet of 140 random robots needs only a few dozen graphs.
#include <memory>
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/model/footprint.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/obstacle_index.h"
#include "fleet_planner/runtime/resource_limits.h"
#include "fleet_planner/model/state_graph.h"

namespace fleet_planner {

class FleetGraphs {
 public:
  /// Builds one graph per distinct discretised footprint, on up to `threads` threads (the result
  /// does not depend on the thread count). Throws InvalidInput for an unusable footprint, and,
  /// before allocating anything in proportion to the map, ResourceLimitError for more robots
  /// than limits.max_robots, a map larger than limits.max_map_cells, or graphs whose estimated
  /// memory (resource_limits.h) on top of the process's resident memory exceeds
  /// limits.max_memory_mb. The deadline is checked before each graph (a few milliseconds on a
  /// 256 x 256 map): throws DeadlineExpired if it passes before every graph is built.
  FleetGraphs(const GridMap& map, const std::vector<Footprint>& footprints, ActionModel model = {},
              int threads = 1, const ResourceLimits& limits = {}, const Deadline& deadline = {});

  /// Some robots of `all` (their indices, in this order), sharing its graphs: robot i here is
  /// robot robots[i] there. Throws InvalidInput for an index out of range.
  FleetGraphs(const FleetGraphs& all, const std::vector<int>& robots);

  int numRobots() const { return static_cast<int>(robot_graph_.size()); }
  int numGraphs() const { return static_cast<int>(graphs_.size()); }
  const StateGraph& graph(int robot) const { return *graphs_[robot_graph_[robot]]; }
  const FootprintCells& cells(int robot) const { return graph(robot).cells(); }
  /// Index of the shared graph robot `robot` uses (robots with equal index share a graph).
  int graphIndex(int robot) const { return robot_graph_[robot]; }
  const ObstacleIndex& obstacles() const { return obstacles_; }
  /// Robots whose discretised footprints are equal share a group (and a graph): the group of
  /// each robot and one FootprintCells per group. Throws InvalidInput for an unusable footprint.
  struct Groups {
    std::vector<std::shared_ptr<const FootprintCells>> cells;
    std::vector<int> of_robot;
  };
  static Groups group(const std::vector<Footprint>& footprints, int step);
  /// Sum over robots of their graph's valid states.
  long long totalStates() const;
  std::size_t memoryBytes() const;

 private:
  FleetGraphs(const GridMap& map, Groups groups, ActionModel model, int threads, const ResourceLimits& limits,
              const Deadline& deadline);
  /// `map`, after the limits' checks (throws ResourceLimitError).
  static const GridMap& admit(const GridMap& map, const Groups& groups, const ResourceLimits& limits);

  ObstacleIndex obstacles_;
  std::vector<std::shared_ptr<const StateGraph>> graphs_;
  std::vector<int> robot_graph_;
};

}  // namespace fleet_planner
