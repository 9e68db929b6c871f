#pragma once
/// Conflicts among the agents of one subproblem, for the backends (the validator has its own,
/// independent code). Paths are state ids at t = 0, 1, ...; an ended path stays at its end.
#include <optional>
#include <vector>

#include "fleet_planner/solvers/search_space.h"

namespace fleet_planner {

using StatePath = std::vector<StateId>;

struct AgentConflict {
  enum class Kind { Vertex, Transfer };
  Kind kind = Kind::Vertex;
  int a = -1, b = -1;
  int t = 0;  ///< vertex: the time both stand; transfer: the step t -> t + 1
};

inline StateId stateAt(const StatePath& p, int t) {
  return t < static_cast<int>(p.size()) ? p[t] : p.back();
}

/// The earliest conflict (by step; at one step, vertex conflicts at t + 1 before transfers of t;
/// then by agent pair), or nullopt.
std::optional<AgentConflict> firstConflict(const SearchSpace& space, const std::vector<StatePath>& paths);

/// Number of (pair, step) with a vertex or transfer conflict.
int countConflicts(const SearchSpace& space, const std::vector<StatePath>& paths);

/// Conflicts of agent a doing `action` from s at step t with the other agents' paths.
int conflictsWith(const SearchSpace& space, const std::vector<StatePath>& paths, int a, StateId s, Action action,
                  int t);

}  // namespace fleet_planner
