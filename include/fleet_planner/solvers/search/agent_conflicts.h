#pragma once
/// Conflicts among the agents of one subproblem, for the backends (the validator has its own,
/// independent code). Paths are state ids at t = 0, 1, ...; an ended path stays at its end; an
/// empty path is an agent left out (it conflicts with nobody).
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "fleet_planner/solvers/search/search_space.h"

namespace fleet_planner {

using StatePath = std::vector<StateId>;

struct AgentConflict {
  enum class Kind { Vertex, Transfer };
  Kind kind = Kind::Vertex;
  int a = -1, b = -1;
  int t = 0;  ///< vertex: the time both stand; transfer: the step t -> t + 1
  Cell cell;  ///< a cell both footprints (vertex) or both sweeps (transfer) cover
};

inline StateId stateAt(const StatePath& p, int t) {
  return t < static_cast<int>(p.size()) ? p[t] : p.back();
}

/// The earliest conflict (by step; at one step, vertex conflicts at t + 1 before transfers of t;
/// then by agent pair), or nullopt.
std::optional<AgentConflict> firstConflict(const SearchSpace& space, const std::vector<StatePath>& paths);

/// The earliest conflict of each conflicting agent pair, in the order of firstConflict(), at
/// most `max_count` of them (the candidates LA-CBS classifies before it splits).
std::vector<AgentConflict> earliestConflictPerPair(const SearchSpace& space, const std::vector<StatePath>& paths,
                                                   int max_count);

/// Like earliestConflictPerPair(), over the conflicts `accept` returns true for only.
std::vector<AgentConflict> earliestConflictPerPair(const SearchSpace& space, const std::vector<StatePath>& paths,
                                                   int max_count,
                                                   const std::function<bool(const AgentConflict&)>& accept);

/// The agent pairs (a < b) with at least one conflict, sorted.
std::vector<std::pair<int, int>> conflictingPairs(const SearchSpace& space, const std::vector<StatePath>& paths);

/// countConflicts() and conflictingPairs() in one pass over the conflicts.
struct ConflictTally {
  int conflicts = 0;
  std::vector<std::pair<int, int>> pairs;
};
ConflictTally tallyConflicts(const SearchSpace& space, const std::vector<StatePath>& paths);

/// Number of (pair, step) with a vertex or transfer conflict.
int countConflicts(const SearchSpace& space, const std::vector<StatePath>& paths);

/// The other agents' motions step by step, for counting a candidate move's conflicts with them
/// (CBS's conflict-avoidance table). Built once per low-level search.
class ConflictAvoidanceTable {
 public:
  ConflictAvoidanceTable(const SearchSpace& space, const std::vector<StatePath>& paths, int agent);
  /// Conflicts of the agent doing `action` from s during step t with the other agents.
  int conflicts(StateId s, Action action, int t) const;

 private:
  struct Motion {
    const CellSet* cells;
    Cell origin;
  };
  const SearchSpace& space_;
  int agent_;
  std::vector<std::vector<Motion>> steps_;  // per step: the others' sweeps; the last repeats
};

}  // namespace fleet_planner
