#pragma once
/// Random LA-MAPF instances with the paper's distribution (Results section): half circles with
/// radius in [0.4, 2.0] cells, half blocks with min_x in [-2, -0.2], max_x in [0.2, 2.0] and
/// half-width in [0.2, 2.0], every size a multiple of 0.1. Starts are valid and pairwise
/// non-overlapping, targets likewise, and each target is reachable from its start in the
/// robot's own state graph. Seeded and deterministic.
///
/// Beyond the paper, `polygon_share` turns that share of the non-circle robots into random
/// polygons (3 to 8 vertices around the origin at random radii in [min_size, max_size], convex
/// or not, sometimes shifted so that the origin lies off-centre or outside), for tests that need
/// every footprint kind. At 0 (the default) the instances are exactly the paper's.
#include <cstdint>

#include <vector>

#include "fleet_planner/model/action.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/runtime/random.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/instance.h"

namespace fleet_planner {

struct GeneratorOptions {
  int robots = 10;
  std::uint64_t seed = 0;
  ActionModel model;
  int attempts_per_robot = 2000;  ///< start/target draws before giving up on a robot
  double min_size = 0.2;          ///< smallest block half-extent (cells)
  double max_size = 2.0;          ///< largest circle radius / block half-extent (cells)
  double min_radius = 0.4;        ///< smallest circle radius (cells)
  double polygon_share = 0.0;     ///< chance that a non-circle robot is a polygon, in [0, 1]
  /// The sweep tolerance (Footprint::sweep_tolerance) of the model the feasibility check
  /// (feasible_instances.h) decides pairs in, and robots are drawn again in: that of the solves
  /// the instance is made for. The first draw does not depend on it; the footprints written
  /// carry none.
  double check_sweep_tolerance = 0.0;
};

/// Robots alternate circle, block (or polygon), circle, ... and are named "0", "1", ... Throws InvalidInput
/// naming the robot when one cannot be placed within its attempts (map too full or too tight).
Instance generateInstance(const GridMap& map, const GeneratorOptions& options);

/// Draws robot `robot`'s start and target anew (its footprint kept, its graph in `graphs`): a
/// valid start clear of the starts of the robots marked in `others`, a target reachable from it
/// clear of their targets. False, the robot unchanged, when `attempts` draws find none.
bool placeRobot(const FleetGraphs& graphs, Instance& instance, int robot, const std::vector<bool>& others,
                Rng& rng, int attempts);

}  // namespace fleet_planner
