#pragma once
/// Checks of an instance against its map, before any planning (paper: Preliminaries,
/// "Solvability of MAPF instance").
#include <string>
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/footprint_cells.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/instance.h"

namespace fleet_planner {

/// Empty if a robot with these cells can stand at `pose`, otherwise why not: "has heading outside
/// 0..3", "is off the W x H map", "footprint leaves the map", "footprint covers the blocked cell
/// (x,y)".
std::string poseProblem(const GridMap& map, const FootprintCells& cells, const GridPose& pose);

/// Throws InvalidInput, naming the robot and where it came from, for input that cannot be
/// planned at all: duplicate or empty ids, an unusable footprint, a footprint larger than the
/// map, a start or target with a bad heading, off the map, or whose footprint covers a blocked
/// or off-map cell.
void validateInstance(const GridMap& map, const Instance& instance);

struct RobotProblem {
  enum class Kind { InvalidStart, InvalidTarget, Unreachable, StartsOverlap, TargetsOverlap };
  int robot = -1;
  int other = -1;  ///< the second robot of an overlap
  Kind kind = Kind::Unreachable;
  std::string reason;  ///< starts with the robot's label
};

struct SolvabilityReport {
  std::vector<RobotProblem> problems;
  /// False if the deadline passed before every robot was checked: the problems are those found
  /// until then.
  bool complete = true;
  bool solvable() const { return problems.empty(); }
  /// The problems, one per line.
  std::string summary() const;
};

/// The solvability pre-check, per robot: start and target valid in its state graph, target
/// reachable from start; and per pair: starts do not overlap, targets do not overlap. Passing
/// it is necessary, not sufficient, for the instance to be solvable. The deadline is checked
/// before each robot (one search of its state graph).
SolvabilityReport checkSolvability(const Instance& instance, const FleetGraphs& graphs, const Deadline& deadline = {});

}  // namespace fleet_planner
