#pragma once
/// How the layered planner divides a call's deadline and effort between its stages, in one place
/// (docs/design.md has the table). Shares are of the time left when the stage starts. The
/// defaults are the planner's; LayeredOptions::budget sets them per call.
#include <cstddef>

namespace fleet_planner {

struct TimeBudget {
  /// The decomposition may take at most this share; one cut short is still legal, only coarser.
  double decomposition_share = 0.5;
  /// Kept from solving for merging the subproblems' plans and validating: this share of the
  /// time left, at most merge_reserve_max_s seconds.
  double merge_reserve_share = 0.1;
  double merge_reserve_max_s = 3.0;
  /// Kept from refinement and compression (optional work) for the final validation: these
  /// seconds, at most half of the time left.
  double validation_reserve_s = 1.0;
  /// A subproblem's share of the time left: its part of the robots still to solve in the round,
  /// at least this much (the last subproblem gets all of it). Half: a hard level of a large
  /// fleet needs a good part of the call, and a failed one still leaves the safeguard half.
  double min_subproblem_share = 0.5;
  /// Part of a subproblem's share left to the fallback backend, when there is one.
  double fallback_share = 0.5;
  /// Pair proofs (infeasible_pairs.h): the share of the time left that the entangled pairs may
  /// take before solving, and each failed subproblem's pairs after it fails; the LA-LaCAM
  /// expansions of each pair; the pairs tried per failure.
  double pair_proof_share = 0.1;
  long long pair_proof_expansions = 4'000'000;
  std::size_t pairs_per_failure = 120;
  /// Serial backends: low-level expansions per robot a level may spend planning around the timed
  /// paths of its cluster's earlier levels before it is planned at their targets and delayed
  /// instead (a count, so the outcome does not depend on the machine). Generous: a packed
  /// level's parking plan among those paths may get every robot home only after many
  /// expansions, and its plan has none of the second attempt's delays.
  long long chain_expansions_per_robot = 100'000;
  /// Step aside (step_aside.h): standing robots within this many cells of a failed subproblem's
  /// shortest paths may step aside; as many as its robots (the nearest), at least
  /// step_aside_min_count.
  int step_aside_margin = 2;
  std::size_t step_aside_min_count = 8;
  /// And, for a subproblem of at most step_aside_plan_max_robots robots (a knot; a large level
  /// seldom finds its plan alone in that time either), the standing robots on the paths of a
  /// plan of its robots alone among the static obstacles (LA-LNS), found within this share of
  /// the time left, at most step_aside_plan_max_s seconds.
  std::size_t step_aside_plan_max_robots = 8;
  double step_aside_plan_share = 0.1;
  double step_aside_plan_max_s = 2.0;
  /// A decomposition whose largest subproblem holds at least this share of the robots, and at
  /// least whole_fleet_min_robots of them, is set aside and the fleet solved as one subproblem:
  /// the other levels would be planned around (or delayed behind) that packed subproblem's long
  /// plan, which costs more than planning them in it. Above 1: never.
  double whole_fleet_share = 0.5;
  std::size_t whole_fleet_min_robots = 16;
  /// On the default lattice (PlanningOptions::lattice_step 0) of a step above 1: the fleet has
  /// this share of the call's time there; if it times out, the rest goes to a lattice twice as
  /// coarse (plan_fleet.h). 1: the default lattice has all of it.
  double default_lattice_share = 2.0 / 3.0;
};

}  // namespace fleet_planner
