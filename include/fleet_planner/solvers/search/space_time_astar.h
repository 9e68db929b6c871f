#pragma once
/// Low-level search of the serial backends: space-time A* for one agent over its restricted
/// state graph, under CBS constraints and the reservation table of moving obstacles, with the
/// exact distance to the target as heuristic (Silver 2005; Sharon et al. 2015, low level).
///
/// Once past the last time at which any constraint or reservation changes, the world is static,
/// so states (s, t) for later t are merged into (s, T_static): the search space is finite and an
/// agent without any path is reported as such instead of searching forever.
#include <cstdint>
#include <functional>
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/solvers/search/agent_constraints.h"
#include "fleet_planner/solvers/search/search_space.h"

namespace fleet_planner {

struct LowLevelOptions {
  long long max_nodes = 4'000'000;  ///< generated nodes before giving up (memory bound)
  /// Expansions after which a search under area constraints computes where it can still finish
  /// and prunes the rest (three backward searches over the agent's graph; see the .cpp).
  long long area_bounds_after = 10'000;
  /// Tie-breaker among equal f: number of conflicts of doing `action` from `s` at step t with
  /// the other agents' current paths (fewer first). May be empty.
  std::function<int(StateId s, Action action, int t)> conflicts;
  /// Above 1: a focal search (Pearl and Kim 1982; ECBS's low level, Barer et al. 2014): among
  /// the open nodes whose f is at most this weight times the least open f, fewest `conflicts`
  /// first. The path found costs at most the weight times the optimum, and the result's
  /// lower_bound is the least open f when it was found.
  double focal_weight = 1.0;
  /// Steps the search may not take besides those the constraints and reservations forbid (may
  /// be empty): `blocked(s, action, t)`, the same for every t after `blocked_until`. A target
  /// that it blocks for some time must be told to the search by a cost bound (requireCostAbove).
  std::function<bool(StateId s, Action action, int t)> blocked;
  int blocked_until = -1;
};

struct LowLevelResult {
  enum class Outcome { Found, NoPath, Expired, NodeLimit };
  Outcome outcome = Outcome::NoPath;
  std::vector<StateId> path;  ///< states at t = 0, 1, ..., ending at the target
  long long expansions = 0;
  /// Found: a lower bound on the cost of any path under the constraints (the path's cost
  /// unless the search was focal).
  int lower_bound = 0;
};

/// Cheapest path for agent `a` from its start to its target that it can hold forever after,
/// under `constraints` (including their bounds on the cost).
LowLevelResult spaceTimeAStar(const SearchSpace& space, int a, const AgentConstraints& constraints,
                              const Deadline& deadline, const LowLevelOptions& options = {});

/// The action taking agent a from `from` to `to` in one step (Wait when equal).
Action stepAction(const StateGraph& graph, StateId from, StateId to);

}  // namespace fleet_planner
