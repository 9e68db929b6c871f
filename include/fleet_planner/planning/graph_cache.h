#pragma once
/// The state graphs of the last call, kept for the next one: building them is the largest fixed
/// cost of a call (seconds on a large map), and a node plans the same fleet on the same map again
/// and again. Thread-safe; one graph set at a time.
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "fleet_planner/model/fleet_graphs.h"

namespace fleet_planner {

class GraphCache {
 public:
  /// The graphs of `footprints` on `map`: the cached ones when `map_version`, the footprints and
  /// the model are those they were built for, else new ones (the old ones are freed first).
  /// `cached` says which. Throws DeadlineExpired or ResourceLimitError as FleetGraphs does.
  std::shared_ptr<const FleetGraphs> get(const GridMap& map, std::uint64_t map_version,
                                         const std::vector<Footprint>& footprints, const ActionModel& model,
                                         int threads, const ResourceLimits& limits, const Deadline& deadline,
                                         bool& cached);

 private:
  std::mutex mutex_;
  std::uint64_t map_version_ = 0;
  std::vector<Footprint> footprints_;
  ActionModel model_;
  std::shared_ptr<const FleetGraphs> graphs_;
};

}  // namespace fleet_planner
