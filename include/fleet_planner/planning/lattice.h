#pragma once
/// The planning lattice: states every `step` map cells (ActionModel::step), so that the number of
/// states and the length of every path in steps follow the problem, not the map's resolution.
/// Footprints and sweeps stay on the map's own cells (footprint_cells.h), so nothing narrower than
/// a robot is ever closed by coarsening.
///
/// Each robot plans on its own lattice: a start or target off it is connected by at most one
/// rotation and one short move (under `step` cells) at each end:
///   start -> [rotate] -> [short move] -> lattice start ... lattice plan ... lattice target ->
///   [short move] -> [rotate] -> target.
/// The starts' connections run together before the lattice plan (checked by the validator); each
/// target's connection runs at the earliest step after its robot arrives at which it meets no
/// other robot's motion, then the robot stays at its target.
#include <optional>
#include <string>
#include <vector>

#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/instance_check.h"
#include "fleet_planner/model/plan.h"
#include "fleet_planner/model/robot_cells.h"

namespace fleet_planner {

/// The default lattice step of a fleet, in cells: a third of the narrowest robot's width (its
/// footprint's smaller extent), at least 1. The paper's benchmark robots (1-4 cells) plan at 1;
/// robots of 0.3-1 m on a 0.05 m map at 2-6.
int defaultLatticeStep(const Instance& instance);

/// One robot's way onto its lattice and off it.
struct LatticeConnection {
  Path prefix;  ///< start .. lattice start (one pose if the start is on the lattice)
  Path suffix;  ///< lattice target .. target (one pose if the target is on the lattice)
};

struct LatticeInstance {
  Instance instance;  ///< the robots with their lattice starts and targets
  std::vector<LatticeConnection> connections;
  std::string problem;  ///< why the fleet cannot be put on this lattice (empty: it can)
  /// A start or target that cannot be connected on any lattice (its turn from or to its yaw hits
  /// a wall, no free state there): INVALID_START / INVALID_TARGET with the reason and a cell.
  std::vector<RobotProblem> problems;
};

/// Chooses each robot's connections on `graphs` (built with ActionModel::step = `step`): motions
/// free on the map, starts' connections that, run together, meet no other robot's, and of those
/// the fewest connecting steps plus steps of the robot's way on the lattice offset they choose
/// (alone on the map; the order of connecting steps alone past a budget of A* expansions).
/// The robots' choices are made on `threads` threads; the answer does not depend on them.
LatticeInstance connectToLattice(const GridMap& map, const Instance& instance, const FleetGraphs& graphs, int step,
                                 int threads = 1);

/// Robot a and robot b along their paths meet at some step u >= from: the cells they cover during
/// step u share one (after its path a robot stays at rest).
bool pathsMeet(const RobotCells& a, const Path& pa, const RobotCells& b, const Path& pb, int from,
               const ActionModel& model);

/// The full plan of `instance` (the robots as given, yaws included): the starts' connections (all together, padded with waits), the
/// lattice plan, and each target's connection at its earliest safe step. Nothing if some target's
/// connection never becomes safe (another robot ends on its way); `problem` says which.
std::optional<Plan> assembleLatticePlan(const Instance& instance, const LatticeInstance& lattice,
                                        const FleetGraphs& graphs, const Plan& lattice_plan, std::string& problem);

}  // namespace fleet_planner
