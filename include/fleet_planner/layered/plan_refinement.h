#pragma once
/// Plan refinement (beyond the paper): replan robots one at a time around everybody else.
///
/// Layering has a price: a robot of an early subproblem plans around the start footprints of
/// later robots that have long left, and a robot of a late one waits for whole levels. Once a
/// merged plan exists, each robot whose cost exceeds its distance to the target is replanned
/// around every other robot's path (moving obstacles) for its earliest arrival before its
/// current cost, by a safe interval search (safe_interval_search.h: a wait is one node, so a
/// path that waits long for others to pass costs a few expansions). A cheaper path replaces
/// the old one; it conflicts with nobody by construction, so the plan stays valid. This is a
/// neighbourhood-of-one large neighbourhood search (Li et al., "Anytime Multi-Agent Path
/// Finding via Large Neighborhood Search", IJCAI 2021) with the current plan as incumbent.
///
/// A single robot often cannot improve because others stand in the way of its cheaper paths:
/// when a pass of single searches improves nothing, each delayed robot is replanned together
/// with the (up to group_size - 1) robots whose paths cover most of its ideal path: in turn
/// (prioritized planning, the delayed robot first, each member around the rest and the members
/// before it), the way MAPF-LNS repairs a neighbourhood; the group's new paths are kept when
/// their sum of costs drops and none of them ends after the plan's makespan. So neither the SOC
/// nor the makespan ever grows. A search that failed is not repeated until some path changes.
///
/// Robots are visited in decreasing order of their delay (ties: index), and passes repeat
/// until one improves nothing, or a limit (passes, expansions) or the deadline is reached. Without the
/// deadline cutting in, the result is deterministic.
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"

namespace fleet_planner {

struct RefinementOptions {
  int max_passes = 4;
  /// Safe-interval expansions of all searches together, per robot of the plan (checked before
  /// each search, a group's member searches included): bounds the refinement's work the same
  /// way on every machine.
  long long expansions_per_robot = 30'000;
  long long max_expansions = 300'000;  ///< and at most this many in all
  long long max_nodes_per_search = 50'000;  ///< expansions of one search (a group: of each member's)
  /// A single search orders its nodes by arrival + weight x distance to the target: the first
  /// path it finds arrives before the robot's current arrival, not necessarily at the earliest.
  double heuristic_weight = 2.0;
  int group_size = 4;  ///< robots per group search; < 2: none
};

struct RefinementStats {
  int passes = 0;
  int searches = 0;
  int group_searches = 0;
  long long expansions = 0;
  bool deadline_hit = false;  ///< stopped by the deadline: the result may depend on timing
  int improved = 0;          ///< replacements made
  long long soc_saved = 0;   ///< SOC before minus after
  double time_s = 0.0;
};

/// Refines a conflict-free plan (one path per robot of `instance`, instance order) in place.
RefinementStats refinePlan(const Instance& instance, const FleetGraphs& graphs, std::vector<Path>& paths,
                           const Deadline& deadline, const RefinementOptions& options = {});

}  // namespace fleet_planner
