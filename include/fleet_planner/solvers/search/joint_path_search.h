#pragma once
/// Joint space-time A* for a small group of agents (two or three) of LA-LNS (la_lns.h): the
/// group moves as one, so a robot can leave its target to let a partner pass and come back, or
/// two robots can trade places through a pocket that a third one clears, which replanning one
/// robot at a time never finds (each one's best answer to the others' fixed paths is to collide
/// once). A* over joint states, as in Standley, "Finding Optimal Solutions to Cooperative
/// Pathfinding Problems", AAAI 2010, without its operator decomposition.
///
/// Group members never collide with one another; the agents outside the group are soft
/// obstacles, as in soft_path_search.h (each colliding step costs `collision_cost`); static
/// footprints and other subproblems' moving obstacles are hard. A member at its target may
/// commit to it (it then stays for good, and the agents it would meet there are charged); every
/// step costs 1 for each member not committed, so the answer minimises the group's sum of costs
/// plus the collision penalty, as the exhaustive search of the tests does. Joint states past the
/// last change of the world collapse in time, so a group that cannot reach its targets is
/// proven so (NoPath) once its reachable joint space is exhausted.
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/solvers/search/soft_path_table.h"

namespace fleet_planner {

struct JointSearchOptions {
  /// Cost of one colliding step with an agent outside the group, in steps of path length.
  int collision_cost = 16;
  /// Joint states stored before the search gives up (NodeLimit). An expansion stores up to 5^n
  /// of them (n robots), so this bounds time and memory alike: on maze-128-128-10, 500,000
  /// took 0.35-0.4 s for three robots and 0.5-0.9 s for two (longer paths, more expansions).
  long long max_nodes = 50'000;
  /// A search that starts later: the members at these states (the group's order) at step
  /// `from_step`, their paths before it being the caller's (and the answer's paths holding the
  /// states from from_step on). Empty: at their starts at step 0.
  std::vector<StateId> from;
  int from_step = 0;
  /// Joint states that differ only in a step after this one are taken as the same (>= 0; by
  /// default the step from which the soft agents and the reservations stop moving, where that
  /// is exact). An earlier one, the step after which the agents near the group stop, makes far
  /// fewer states when robots far away drive on for long: every collision is still counted at
  /// its true step, but a plan that waits for a pass after it may be missed, so NoPath is then
  /// no proof.
  int static_from = -1;
};

struct JointSearchResult {
  enum class Outcome { Found, NoPath, Expired, NodeLimit };
  Outcome outcome = Outcome::NoPath;
  /// One path per member (the group's order): states at t = from_step, from_step + 1, ...
  /// (JointSearchOptions), ending at the target, held from then on.
  std::vector<StatePath> paths;
  int collisions = 0;  ///< colliding steps with agents outside the group, plus those met holding
  long long expansions = 0;
};

/// The largest group jointPathSearch() takes.
constexpr int kMaxJointGroup = 3;

/// Cheapest joint paths of the `group` (1 to kMaxJointGroup distinct agents, none of them in
/// `soft`) from their starts to their targets under that cost.
JointSearchResult jointPathSearch(const SearchSpace& space, const std::vector<int>& group,
                                  const SoftPathTable& soft, const Deadline& deadline,
                                  const JointSearchOptions& options = {});

}  // namespace fleet_planner
