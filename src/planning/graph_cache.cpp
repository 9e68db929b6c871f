// The state graphs kept between calls; see graph_cache.h.
#include "fleet_planner/planning/graph_cache.h"

namespace fleet_planner {

std::shared_ptr<const FleetGraphs> GraphCache::get(const GridMap& map, std::uint64_t map_version,
                                                   const std::vector<Footprint>& footprints,
                                                   const ActionModel& model, int threads,
                                                   const ResourceLimits& limits, const Deadline& deadline,
                                                   bool& cached) {
  std::lock_guard<std::mutex> lock(mutex_);
  cached = graphs_ && map_version_ == map_version && footprints_ == footprints &&
           model_.allow_backward == model.allow_backward && model_.step == model.step;
  if (!cached) {
    graphs_.reset();  // free the old graphs before building new ones
    graphs_ = std::make_shared<const FleetGraphs>(map, footprints, model, threads, limits, deadline);
    map_version_ = map_version;
    footprints_ = footprints;
    model_ = model;
  }
  return graphs_;
}

}  // namespace fleet_planner
