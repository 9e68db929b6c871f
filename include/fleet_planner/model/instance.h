#pragma once
/// An LA-MAPF instance: robots with footprints, start and target states.
#include <optional>
#include <string>
#include <vector>

#include "fleet_planner/model/footprint.h"
#include "fleet_planner/model/types.h"

namespace fleet_planner {

struct Robot {
  std::string id;  ///< unique name, used in every message about the robot
  Footprint footprint;
  GridPose start;
  GridPose target;
  std::string source;  ///< where it was read ("file:line"), for messages; may be empty
  /// The yaw (radians, 0 = +x, counter-clockwise) the robot stands at at its start when that is
  /// not start.heading's: the plan's first step turns it in place onto start.heading.
  std::optional<double> start_yaw;
  /// The yaw it must end at when that is not target.heading's: the plan's last step turns it in
  /// place from target.heading to this yaw (robot_cells.h).
  std::optional<double> target_yaw;
  /// With a start yaw: the step of that turn; the robot rests at its start yaw until then (its
  /// path repeats its first pose up to start_turn + 1). 0 for a plan from scratch; a robot given a
  /// new goal while the fleet drives rests at its previous goal's yaw until its new way begins
  /// (execution/replanning.h).
  int start_turn = 0;
  /// Conflicts of its path with other robots' are checked from this step on (validatePlan). 0
  /// for a plan from scratch; after a new goal given while the fleet drives, the step it arrived
  /// at its previous goal: before it, its path is the rest there, a history it did not drive
  /// that only meets steps other robots had done (execution/replanning.h).
  int conflicts_from = 0;
};

struct Instance {
  std::vector<Robot> robots;
  std::string map_file;  ///< the map the instance refers to, if the format names one
};

/// "robot '<id>'" plus " (<source>)" when the source is known: the prefix of robot messages.
std::string robotLabel(const Robot& robot);

/// The benchmark's "K mixed" protocol: the first ceil(K/2) circles interleaved with the first
/// floor(K/2) non-circles (blocks and polygons) of the pool, in pool order, circle first; where
/// one kind runs out, the rest are of the other kind. Throws InvalidInput if K is not in
/// [1, pool size].
Instance selectMixed(const Instance& pool, int k);

}  // namespace fleet_planner
