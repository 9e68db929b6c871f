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
#include <unordered_set>
#include <vector>

#include "fleet_planner/core/deadline.h"
#include "fleet_planner/solvers/search_space.h"

namespace fleet_planner {

/// CBS constraints of one agent: not at state s at time t; not doing action a from s at step t.
class AgentConstraints {
 public:
  void forbidState(StateId s, int t);
  void forbidAction(StateId s, Action a, int t);
  bool stateForbidden(StateId s, int t) const {
    return !vertex_.empty() && vertex_.count(vertexKey(s, t)) > 0;
  }
  bool actionForbidden(StateId s, Action a, int t) const {
    return !edge_.empty() && edge_.count(edgeKey(s, a, t)) > 0;
  }
  /// Latest time mentioned by any constraint (-1 if none).
  int maxTime() const { return max_time_; }
  /// Latest time at which the state is forbidden or waiting in it is forbidden (-1 if never).
  int lastBlockedAt(StateId s) const;
  bool empty() const { return vertex_.empty() && edge_.empty(); }

 private:
  static std::uint64_t vertexKey(StateId s, int t) {
    return (static_cast<std::uint64_t>(t) << 32) | static_cast<std::uint32_t>(s);
  }
  static std::uint64_t edgeKey(StateId s, Action a, int t) {
    return (static_cast<std::uint64_t>(t) << 35) | (static_cast<std::uint64_t>(static_cast<std::uint32_t>(s)) << 3) |
           static_cast<std::uint64_t>(a);
  }
  std::unordered_set<std::uint64_t> vertex_, edge_;
  std::vector<std::pair<StateId, int>> waits_;  // (state, t) of vertex and wait constraints
  int max_time_ = -1;
};

struct LowLevelOptions {
  long long max_nodes = 4'000'000;  ///< generated nodes before giving up (memory bound)
  /// Tie-breaker among equal f: number of conflicts of doing `action` from `s` at step t with
  /// the other agents' current paths (fewer first). May be empty.
  std::function<int(StateId s, Action action, int t)> conflicts;
};

struct LowLevelResult {
  enum class Outcome { Found, NoPath, Expired, NodeLimit };
  Outcome outcome = Outcome::NoPath;
  std::vector<StateId> path;  ///< states at t = 0, 1, ..., ending at the target
  long long expansions = 0;
};

/// Cheapest path for agent `a` from its start to its target that it can hold forever after.
LowLevelResult spaceTimeAStar(const SearchSpace& space, int a, const AgentConstraints& constraints,
                              const Deadline& deadline, const LowLevelOptions& options = {});

/// The action taking agent a from `from` to `to` in one step (Wait when equal).
Action stepAction(const StateGraph& graph, StateId from, StateId to);

}  // namespace fleet_planner
