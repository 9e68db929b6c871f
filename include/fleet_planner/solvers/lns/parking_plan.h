#pragma once
/// A collision-free plan for a packed subproblem of LA-LNS (la_lns.h), made one robot at a time
/// with the robots in its way pushed aside. Each robot in turn, from where its path ends:
///   1. its way home through fewest standing robots (A* among the static obstacles, a move among
///      robots standing where their paths end costing `crowd_cost` steps more);
///   2. if that way meets none, a safe interval search drives it home around every path planned
///      so far (a robot stands where its path ends from then on);
///   3. otherwise, or if that search fails, the robots standing on the way (at their starts,
///      their targets or in pockets) drive into pockets off it (pocket_repair.h); one that
///      cannot reach a pocket first has the robots on its own way to one pushed, up to
///      `push_depth` times over; then the robot tries again. A robot pushed off its target is
///      planned again later; one that fails `max_failed_turns` turns is given up.
/// Every leg is collision-free around everything planned before it, so the plan is too; it is
/// checked once more at the end.
///
/// On real maps with 30-50 large robots, almost every way from a robot's start crosses the start
/// of another: no order of prioritized planning plans such a fleet, and the soft repairs of
/// LA-LNS stall with dozens of colliding pairs. Pushing the standing robots aside is what
/// point-agent methods do (Push and Swap: Luna, Bekris, IJCAI 2011; PIBT: Okumura et al.,
/// AIJ 2022); with large robots a pocket is a pose off the way where the footprint fits.
/// Incomplete, and robots drive one after the other where they push each other, so the plan can
/// be long: the layered planner's refinement shortens it. Deterministic.
#include <optional>
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/solvers/search/agent_conflicts.h"

namespace fleet_planner {

struct ParkingPlanOptions {
  int max_pockets = 8;                   ///< pockets tried per pushed robot
  long long max_expansions = 3'000'000;  ///< of all the leg searches together
  /// Turns without a path to its target after which a robot is given up (it stays where it
  /// stands, and is planned by LA-LNS's repairs).
  int max_failed_turns = 4;
  /// A robot's way to clear is its cheapest one when a state among standing robots costs this
  /// many steps more, so that it goes round a crowd it can go round.
  int crowd_cost = 10;
  long long max_way_states = 200'000;  ///< states popped by one search for a way
  /// A robot to push that has no pocket it can reach has the robots on its way to one pushed
  /// first, up to this many times over.
  int push_depth = 4;
  /// fastestParkingPlan: orders that get every agent home within this factor of the fastest
  /// order's expansions stay in the running, and the cheapest of their plans is kept (1: the
  /// fastest order's plan).
  double order_slack = 1;
};

struct ParkingPlan {
  /// Every agent's path (state ids at t = 0, 1, ...), collision-free together; an agent not
  /// home stands where its path ends.
  std::vector<StatePath> paths;
  std::vector<char> home;  ///< the agent's path ends at its target
  int robots_home = 0;
  int order = 0;  ///< fastestParkingPlan: the index of the order it was made in
};

/// The plan as far as it got: until every agent is home, the budget or the deadline runs out,
/// or every agent left has failed options.max_failed_turns turns. Robots take their turns in
/// `order` (every agent once). None only if the final check finds a conflict (a defect). The
/// expansions spent are added to `expansions`.
std::optional<ParkingPlan> parkingPlan(const SearchSpace& space, const std::vector<int>& order,
                                       const Deadline& deadline, const ParkingPlanOptions& options,
                                       long long& expansions);

/// Parking plans of the same agents in several orders: of the orders that get every agent
/// home within `order_slack` times the expansions of the fastest, the plan of least sum of
/// costs (ties: fewer expansions, then the earlier order); else the plan of the order that got
/// most agents home (ties: the earlier order), whose end game is smallest. No order of
/// turns suits every fleet (robots that go a long way first make room for the others in one
/// fleet and block it in the next), and which one does cannot be told beforehand; an order
/// that pushes fewer robots aside tends to end both sooner and cheaper, but not always. An
/// order gives way as soon as it has spent more than the slack allows: it cannot win. The
/// orders run `threads` at a time; the answer (and the expansions added: for each order those
/// it spent up to the slack's count) does not depend on `threads`.
std::optional<ParkingPlan> fastestParkingPlan(const SearchSpace& space,
                                              const std::vector<std::vector<int>>& orders,
                                              const Deadline& deadline,
                                              const ParkingPlanOptions& options, int threads,
                                              long long& expansions);

}  // namespace fleet_planner
