#pragma once
/// Plan compression (beyond the paper): after merging, move every robot's actions as early as
/// they can go without creating a conflict.
///
/// A robot's path keeps its sequence of states; only its waits are dropped. First the whole plan
/// is retimed to its earliest schedule (execution/earliest_schedule.h): every move starts as soon
/// as the robots whose cells it shares before it have left them, all robots at once, so waits
/// that only chains of other robots' waits made necessary go too. Then, one robot at a time, a
/// run of waits is dropped as a whole, or one wait at a time, whenever the robot's shifted
/// remainder conflicts with no other robot's path (vertex and transfer conflicts, parked robots
/// included, as the validator checks them), which may also let two steps swap their order.
/// Robots are visited in index order, and passes repeat until nothing moves, so the result is
/// deterministic; a deadline stops it early with a plan that is still conflict-free. Paths only
/// get shorter, so every robot's cost and the makespan can only drop.
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"

namespace fleet_planner {

struct CompressionStats {
  int passes = 0;
  long long waits_removed = 0;
  double time_s = 0.0;
  bool deadline_hit = false;  ///< stopped by the deadline: the result may depend on timing
};

/// Compresses a conflict-free plan (one path per robot of `graphs`, instance order) in place.
CompressionStats compressPlan(const Instance& instance, const FleetGraphs& graphs, std::vector<Path>& paths,
                              const Deadline& deadline);

}  // namespace fleet_planner
