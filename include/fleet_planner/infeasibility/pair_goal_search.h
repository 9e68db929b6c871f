#pragma once
/// Whether two robots, alone on the map, can both reach their targets, decided backwards: a
/// breadth-first search from the pair's goal (both at their targets) over the joint
/// configurations that can reach it, each step an action or a wait of each robot that passes
/// the plan validator's checks (footprints before the step, sweeps; collision.h). A step's conflicts do not depend on the direction of time, so
/// the configurations found are exactly those from which a plan reaches the goal: the pair can
/// be solved if and only if its start is among them.
///
/// Its use is the proof that a pair cannot (infeasible_pairs.h). A search forwards from the
/// start (LA-LaCAM) must exhaust every configuration the pair can reach, which on an open map
/// is most of them; this one exhausts those that can reach the goal, which are few when the
/// goal is locked: e.g. two wide robots whose targets are side by side in the open, each of
/// which can only arrive, or turn, through the other's target.
#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/types.h"

namespace fleet_planner {

enum class PairReach {
  Reachable,    ///< the start can reach the goal: the pair has a plan
  Unreachable,  ///< every configuration that can reach the goal was found; the start is not one
  Unknown,      ///< stopped at `max_configurations` or at the deadline
};

struct PairEnds {
  int robot = -1;  ///< index into the fleet graphs
  GridPose start;
  GridPose target;
};

struct PairSearch {
  PairReach reach = PairReach::Unknown;
  long long configurations = 0;  ///< found that can reach the goal (the goal included)
};

/// Searches backwards from (a.target, b.target), at most `max_configurations` configurations.
PairSearch searchPairBackwards(const FleetGraphs& graphs, const PairEnds& a, const PairEnds& b,
                               long long max_configurations, const Deadline& deadline);

}  // namespace fleet_planner
