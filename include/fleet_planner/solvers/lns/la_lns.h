#pragma once
/// LA-LNS: large neighbourhood search that repairs collisions, for large agents.
///   Li, Chen, Harabor, Stuckey, Koenig. "MAPF-LNS2: Fast Repairing for Multi-Agent Path
///   Finding via Large Neighborhood Search." AAAI 2022.
///
/// Every agent first gets a path by prioritized planning in which earlier agents' paths are soft
/// obstacles (soft_path_search.h): the plan is complete but may collide. A subproblem of
/// `parking_robots` or more starts instead with the robots that get home one at a time, pushing
/// the robots that stand in their way into pockets (parking_plan.h); the robots left start from
/// their shortest paths (on packed real maps no order of prioritized planning works, and soft
/// repairs alone stall). Then, until no two agents collide or the deadline passes, a few agents
/// (a neighbourhood) lose their paths and are replanned one by one, in a seeded random order,
/// around everybody else as soft obstacles; the new paths are kept when the number of colliding
/// agent pairs does not grow. Neighbourhoods come
/// from the collision graph (a colliding agent and its partners, widened by a random walk), from
/// the agents in the way of a colliding agent's ideal path, or at random among colliding agents,
/// chosen adaptively by how much each has helped (adaptive LNS). When repairs stop lowering the
/// number of colliding pairs, the neighbourhood doubles until one does; at the size of the
/// subproblem every agent is replanned, colliding or not: a knot of a few pairs in a packed level
/// may need all of its robots to move differently. A fourth kind of step replans a colliding
/// agent and up to two of its partners together around everybody else, for the knots that
/// one-by-one replanning cannot untie: one after the other, collision-free, with the ones not
/// yet replanned at their starts, in a random order and in reverse (ordered_repair.h); where
/// that fails, each of them in turn driving through while the others wait in pockets off its
/// way or beside it (pocket_repair.h); then by LA-CBS (joint_repair.h); then, without moving
/// obstacles, alone among the static obstacles by LA-LaCAM; and where that fails too, once the
/// neighbourhood has grown to the whole subproblem, by a joint search (joint_path_search.h).
///
/// A subproblem with returning robots (robots of other subproblems stepping aside) is first
/// tried as a stage to clear (stage_clearing.h): the others planned without them, the returning
/// robots in that plan's way parked in pockets meanwhile.
///
/// Beyond the paper's backends. Serial: static footprints and the timed paths of other
/// subproblems are hard obstacles. Incomplete: the only proofs it gives are a knot whose joint
/// search exhausts its joint space, or a pair of a knot that cannot reach its targets even alone
/// among the static obstacles (INFEASIBLE, naming the robots); any other unsolved subproblem is
/// TIMEOUT. Same input and seed, same plan. When the caller has something else to try
/// (Subproblem::may_give_up), it answers TIMEOUT as soon as `stall_repairs` repairs with every
/// agent in the neighbourhood bring no fewer colliding pairs (`knot_stall_repairs` for a
/// subproblem of at most `joint_robots` robots), rather than at the deadline; when the caller
/// has another way to plan the whole subproblem (Subproblem::ends_when_stalled), as soon as
/// `end_stall_repairs` repairs in a row bring no new lowest number of colliding pairs.
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

struct LaLnsOptions {
  /// Agents replanned together in one repair step, at first.
  int neighborhood_size = 8;
  /// Repairs without a new lowest number of colliding pairs after which the neighbourhood
  /// doubles (up to every agent of the subproblem).
  int stall_repairs = 10;
  /// The same for a subproblem of at most `joint_robots` robots: each of its repairs is already
  /// the joint repair of all of it, every method of it (the same searches again, in another
  /// order, a group's joint searches not repeated while no path is kept), so it is stuck
  /// sooner. Counts only for giving up (Subproblem::may_give_up).
  int knot_stall_repairs = 2;
  /// Repairs in a row without a new lowest number of colliding pairs after which a subproblem
  /// whose caller has another way to plan it (Subproblem::ends_when_stalled) ends: TIMEOUT,
  /// "no fewer colliding pairs in N repairs".
  int end_stall_repairs = 10;
  /// Cost of one colliding step in the low level, in steps of path length.
  int collision_cost = 16;
  /// Expansions of one low-level search before it gives up.
  long long max_expansions_per_search = 200'000;
  /// Heuristic weight of the soft low-level search (SoftSearchOptions::heuristic_weight): its
  /// paths cost at most this factor more than the cheapest, and it seldom runs out of
  /// expansions where robots must wait for each other.
  double heuristic_weight = 1.5;
  /// Joint repair: agents replanned together, first by LA-CBS (its time, at most a quarter of
  /// what is left, and its expansions), then, if it fails, the group is small enough and the
  /// neighbourhood has grown to the whole subproblem, by a joint search (joint_path_search.h)
  /// storing at most this many joint states (see JointSearchOptions::max_nodes for its cost).
  int joint_size = 3;
  long long joint_search_nodes = 50'000;
  /// The joint search also before the neighbourhood has grown to the whole subproblem, once per
  /// group and number of colliding pairs, when at most this many pairs collide: the knot left
  /// at the end of a large subproblem, which its neighbourhood would take too many repairs to
  /// grow to (0: only at the whole subproblem).
  int joint_search_pairs = 3;
  double joint_seconds = 0.5;
  long long joint_max_expansions = 100'000;
  /// Where the joint search finds nothing, each pair of the group is tried alone among the
  /// static obstacles by LA-LaCAM, with this many expansions: a pair that cannot reach its
  /// targets proves that the subproblem has no plan. Not when the caller may give up
  /// (Subproblem::may_give_up): it has something else to try either way.
  long long pair_proof_expansions = 2'000'000;
  /// Joint repair, after LA-CBS: the group alone among the static obstacles by LA-LaCAM, with
  /// at most this many expansions (0: never) in the time LA-CBS had, when the subproblem has no
  /// moving obstacles (LA-LaCAM does not plan around them); its paths go into the table soft,
  /// whatever they meet of the others.
  long long alone_expansions = 100'000;
  /// A subproblem of at most this many robots takes the joint repair at every repair step:
  /// the other neighbourhoods would replan all of its robots one by one anyway, and the joint
  /// repair also tries them in order, through pockets, by LA-CBS and by LA-LaCAM.
  int joint_robots = 3;
  /// Joint repair, after the ordered one: two agents of the group trading places through a
  /// pocket (pocket_repair.h), with at most this many pockets tried per agent that parks
  /// (0: never), with at most pocket_expansions expansions of its searches in all (doubled
  /// each time it fails for the same group, up to 16 times).
  int pockets = 8;
  long long pocket_expansions = 20'000;
  /// With returning robots, the stage is cleared (stage_clearing.h) only for at most this many
  /// other robots (0: never): a large level seldom finds its plan alone in the time given.
  int stage_robots = 8;
  /// First plan of a subproblem of at least `parking_robots` robots: the robots that get to
  /// their targets one at a time, with the robots in their way pushed into pockets
  /// (parking_plan.h), in at most the larger of `parking_expansions` (0: never) and
  /// `parking_expansions_per_robot` times its robots expansions per order (a fleet of hundreds
  /// needs about as many per robot as one of fifty) and `parking_share` of the time left for
  /// all orders together; the others start from their shortest paths. Smaller subproblems, and
  /// those of fewer than twice `parking_robots` that the parking plan leaves unfinished, start
  /// from the soft first plan, whose robots drive together rather than one after the other.
  int parking_robots = 8;
  long long parking_expansions = 3'000'000;
  long long parking_expansions_per_robot = 60'000;
  double parking_share = 0.7;
  /// Parking plans in the first this many orders of parking_orders.h (1-3: longest way first,
  /// shortest first, crossed targets last); of those that get every robot home within
  /// `parking_order_slack` times the expansions of the fastest, the cheapest is kept
  /// (fastestParkingPlan; 1: the fastest). A third order makes plans about 7 % cheaper on
  /// real maps but costs a third more time on two threads: not the default.
  int parking_orders = 2;
  /// The first order puts a robot after the robots it would shut in or out at its target
  /// (parking_precedence.h), each pair decided within this many expansions (0: never).
  long long parking_precedence_expansions = 20'000;
  double parking_order_slack = 1;
  /// A subproblem of at least this many robots with two threads (the fleet solved as one):
  /// after its first plan, a second search with another seed repairs a copy of it on the other
  /// thread, and the outcome reached after fewer repairs is kept (ties: the first search's), so
  /// that the answer does not depend on which thread runs faster. 0: never.
  int portfolio_robots = 100;
  /// A parking plan that leaves robots short of their targets is finished by its end game
  /// (end_game.h): those robots and the robots on their ways planned together once everybody
  /// else has stopped, in at most `end_game_share` of the time left.
  bool end_game = true;
  double end_game_share = 0.3;
  /// Before each repair, local repairs (path_splice.h): a few steps of a colliding agent's path
  /// around one of its collisions replanned collision-free, the rest kept (delayed if need be).
  bool splice = true;
  /// In a subproblem of more than twice neighborhood_size robots, one local repair of each
  /// colliding agent, in a random order, each kept only if the agent then meets fewer agents
  /// (its windows tried until one does; one that failed is tried again once some path has been
  /// kept); otherwise, or false: one of a random colliding agent, kept unless it meets more. In
  /// fleets of hundreds planned as one, the last pairs are mostly robots parked where a late
  /// robot passes: each steps aside locally.
  bool splice_each_colliding = true;
};

class LaLns : public Solver {
 public:
  explicit LaLns(LaLnsOptions options = {}) : options_(options) {}
  std::string name() const override { return "la_lns"; }
  bool avoidsMovingObstacles() const override { return true; }
  /// Options by name (backend_options.cpp): the fields of the options struct above.
  void configure(const BackendOptionValues& values) override;
  SolveResult solve(const Subproblem& problem) override;

 private:
  LaLnsOptions options_;
};

}  // namespace fleet_planner
