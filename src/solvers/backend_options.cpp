// The options of this package's backends by name (backend_parameters.h): one table per backend,
// each binding a name to a field of its options struct with the values it accepts. A failed
// configure leaves the options as they were.
#include "fleet_planner/solvers/cbs/la_cbs.h"
#include "fleet_planner/solvers/lacam/la_lacam.h"
#include "fleet_planner/solvers/lns/la_lns.h"

namespace fleet_planner {

namespace {
constexpr long long kMaxCount = 1'000'000'000'000LL;
}  // namespace

void LaCbs::configure(const BackendOptionValues& values) {
  LaCbsOptions o = options_;
  OptionBinder bind(name(), values);
  bind.flag("bypass", o.bypass);
  bind.integer("max_candidate_conflicts", o.max_candidate_conflicts, 1, 1000);
  bind.flag("target_candidates", o.target_candidates);
  bind.integer("pairwise_delay_nodes", o.pairwise_delay_nodes, 0, kMaxCount);
  bind.integer("pairwise_delay_expansions", o.pairwise_delay_expansions, 0, kMaxCount);
  bind.integer("max_low_level_nodes", o.max_low_level_nodes, 1, kMaxCount);
  bind.integer("conflict_aware_nodes", o.conflict_aware_nodes, 0, kMaxCount);
  bind.integer("max_high_level_nodes", o.max_high_level_nodes, -1, kMaxCount);
  bind.number("max_memory_mb", o.max_memory_mb, 1, 1e7);
  bind.number("suboptimality", o.suboptimality, 1, 10);
  bind.flag("around_others", o.around_others);
  bind.flag("anytime", o.anytime);
  bind.finish();
  options_ = o;
}

void LaLacam::configure(const BackendOptionValues& values) {
  LaLacamOptions o = options_;
  OptionBinder bind(name(), values);
  bind.number("max_memory_mb", o.max_memory_mb, 1, 1e7);
  bind.number("restart_rate", o.restart_rate, 0, 1);
  bind.finish();
  options_ = o;
}

void LaLns::configure(const BackendOptionValues& values) {
  LaLnsOptions o = options_;
  OptionBinder bind(name(), values);
  bind.integer("neighborhood_size", o.neighborhood_size, 1, 100000);
  bind.integer("stall_repairs", o.stall_repairs, 1, 1000000);
  bind.integer("knot_stall_repairs", o.knot_stall_repairs, 1, 1000000);
  bind.integer("end_stall_repairs", o.end_stall_repairs, 1, 1000000);
  bind.integer("collision_cost", o.collision_cost, 1, 1000000);
  bind.integer("max_expansions_per_search", o.max_expansions_per_search, 1, kMaxCount);
  bind.number("heuristic_weight", o.heuristic_weight, 1, 100);
  bind.integer("joint_size", o.joint_size, 2, 16);
  bind.integer("joint_search_nodes", o.joint_search_nodes, 0, kMaxCount);
  bind.integer("joint_search_pairs", o.joint_search_pairs, 0, 1000000);
  bind.number("joint_seconds", o.joint_seconds, 0, 1e6);
  bind.integer("joint_max_expansions", o.joint_max_expansions, 0, kMaxCount);
  bind.integer("pair_proof_expansions", o.pair_proof_expansions, 0, kMaxCount);
  bind.integer("alone_expansions", o.alone_expansions, 0, kMaxCount);
  bind.integer("joint_robots", o.joint_robots, 0, 16);
  bind.integer("pockets", o.pockets, 0, 100000);
  bind.integer("pocket_expansions", o.pocket_expansions, 1, kMaxCount);
  bind.integer("stage_robots", o.stage_robots, 0, 100000);
  bind.integer("parking_robots", o.parking_robots, 1, 100000);
  bind.integer("parking_expansions", o.parking_expansions, 0, kMaxCount);
  bind.integer("parking_expansions_per_robot", o.parking_expansions_per_robot, 0, kMaxCount);
  bind.number("parking_share", o.parking_share, 0, 1);
  bind.integer("parking_orders", o.parking_orders, 1, 3);
  bind.integer("parking_precedence_expansions", o.parking_precedence_expansions, 0, kMaxCount);
  bind.number("parking_order_slack", o.parking_order_slack, 1, 100);
  bind.integer("portfolio_robots", o.portfolio_robots, 0, 1000000);
  bind.flag("end_game", o.end_game);
  bind.number("end_game_share", o.end_game_share, 0, 1);
  bind.flag("splice", o.splice);
  bind.flag("splice_each_colliding", o.splice_each_colliding);
  bind.finish();
  options_ = o;
}

}  // namespace fleet_planner
