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
#include <unordered_map>
#include <vector>

#include "fleet_planner/core/deadline.h"
#include "fleet_planner/solvers/search_space.h"

namespace fleet_planner {

/// CBS constraints of one agent, on cells: its footprint must not cover cell c at time t, or
/// the cells it sweeps during step t (from t to t + 1) must not include c. A cell shared by two
/// conflicting agents makes every pair of their poses covering it conflict, so forbidding it to
/// one agent or the other splits soundly, and far more strongly than forbidding single states
/// (the mutually conflicting constraint sets of Li et al. 2019).
class AgentConstraints {
 public:
  void forbidCellAt(Cell c, int t) { add({t, c, false}); }
  void forbidCellDuring(Cell c, int t) { add({t, c, true}); }

  /// The footprint at pose p at time t covers a forbidden cell.
  bool poseForbidden(const FootprintCells& cells, const GridPose& p, int t) const;
  /// The sweep of `action` from pose p during step t covers a forbidden cell.
  bool stepForbidden(const FootprintCells& cells, const GridPose& p, Action action, int t) const;
  /// Latest time at which standing at p (or waiting there) is forbidden (-1 if never).
  int lastBlockedAt(const FootprintCells& cells, const GridPose& p) const;
  /// Latest time any constraint speaks of (a step t counts as t + 1); -1 if none.
  int maxTime() const { return max_time_; }
  bool empty() const { return all_.empty(); }

 private:
  struct Entry {
    int t;
    Cell c;
    bool during;  // during step t, not at time t
  };
  void add(const Entry& e);
  std::unordered_map<int, std::vector<Entry>> by_time_;
  std::vector<Entry> all_;
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
