#pragma once
/// One-step configuration generator of LA-LaCAM, PIBT-style, for large agents.
///
/// Agents in priority order take their best next state (by distance to target) whose sweep
/// overlaps neither the sweeps already chosen nor the current footprints of agents still to
/// move. Every action sweeps the agent's current footprint, so an agent can never enter cells
/// another agent holds now, even if that one leaves in the same step. Priority inheritance
/// therefore works one step ahead: when an agent's best state is blocked only by agents still
/// to move, those agents inherit its priority and must move to states clear of the state it
/// wants, while it waits; next step the way is open. Waiting always fits, so a configuration is
/// produced unless the fixed moves clash.
#include <vector>

#include "fleet_planner/core/random.h"
#include "fleet_planner/solvers/search_space.h"

namespace fleet_planner {

using Config = std::vector<StateId>;

class LaPibt {
 public:
  LaPibt(const SearchSpace& space, std::uint64_t seed);

  /// Next states of agent a from s: wait first, then every allowed action's result.
  std::vector<StateId> candidates(int a, StateId s) const;

  /// Fills `next` from `current`: agents in `fixed` (agent, next state) first, in that order,
  /// then the others in `order`. Returns false if the fixed moves cannot all be made.
  bool generate(const Config& current, const std::vector<std::pair<int, StateId>>& fixed,
                const std::vector<int>& order, Config& next);

  Rng& rng() { return rng_; }

 private:
  bool fits(int a, StateId from, Action action, const Config& current) const;
  // Assigns agent a (and, through pushes, agents blocking it). `avoid`: the state of the pusher
  // whose footprint a must leave clear (kNoState: none), `pusher` its agent. Returns false if a
  // could not keep clear of it.
  bool assign(int a, const Config& current, Config& next, int pusher, StateId avoid);
  std::vector<int> blockers(int a, StateId from, Action action, const Config& current) const;

  const SearchSpace& space_;
  Rng rng_;
  std::vector<Action> chosen_;  // action of each assigned agent this step
  std::vector<bool> assigned_;  // assigned, or being assigned (then counted as waiting)
};

}  // namespace fleet_planner
