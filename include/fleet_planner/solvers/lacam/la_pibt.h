#pragma once
/// One-step configuration generator of LA-LaCAM, PIBT-style, for large agents.
///
/// Agents in priority order take their best next state (by distance to target) whose sweep
/// overlaps neither the sweeps already chosen nor the current footprints of agents still to
/// move. Every action sweeps the agent's current footprint, so an agent can never enter cells
/// another agent holds now, even if that one leaves in the same step. Priority inheritance
/// therefore works one step ahead: when an agent's best state is blocked only by agents still
/// to move, those agents inherit its priority and take the first step of their shortest way
/// out of the cells its move would sweep (a turn, for a robot that must turn before it can
/// drive away), while it waits; the way opens in the next steps. Waiting always fits, so a configuration is
/// produced unless the fixed moves clash.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "fleet_planner/runtime/random.h"
#include "fleet_planner/solvers/search/search_space.h"

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
  // Buckets of kBucketCells x kBucketCells map cells, each listing the agents that could sweep
  // one of its cells in the next step from their current state, built once per configuration:
  // fits() and blockers() then check the agents near a motion, not the whole fleet.
  void indexNear(const Config& current);
  // Calls f(b) once for every agent other than a that may sweep a cell of `set` at `origin`.
  template <class F>
  void forNear(int a, const CellSet& set, Cell origin, F&& f) const;
  // Bucket column (row) of map column x (row y), clamped to the map's buckets.
  int bucketX(int x) const { return std::clamp(x / kBucketCells, 0, bx_ - 1); }
  int bucketY(int y) const { return std::clamp(y / kBucketCells, 0, by_ - 1); }
  bool fits(int a, StateId from, Action action, const Config& current) const;
  // Assigns agent a (and, through pushes, agents blocking it). `avoid`: the state the pusher
  // wants next (kNoState: none), `pusher` its agent; a must end clear of the pusher's sweep to
  // it. Returns false if a could not.
  bool assign(int a, const Config& current, Config& next, int pusher, StateId avoid);
  std::vector<int> blockers(int a, StateId from, Action action, const Config& current) const;
  // First steps of a's shortest escapes (within kEscapeDepth steps and kEscapeStates states) to a state whose footprint
  // is clear of `sweep` at `origin`, best first.
  std::vector<int> escapeSteps(int a, StateId from, const CellSet& sweep, Cell origin) const;
  static constexpr int kEscapeDepth = 8;
  static constexpr std::size_t kEscapeStates = 4096;  // bound on one escape search

  static constexpr int kBucketCells = 8;

  const SearchSpace& space_;
  Rng rng_;
  int bx_ = 1, by_ = 1;                      // buckets per row, rows
  std::vector<int> reach_;                   // per agent: cells any sweep reaches from the pose cell
  std::vector<std::vector<int>> near_;       // bucket -> agents
  std::vector<int> filled_;                  // buckets with agents (to clear them)
  mutable std::vector<std::uint32_t> stamp_;  // dedup of forNear
  mutable std::uint32_t query_ = 0;
  std::vector<Action> chosen_;  // action of each assigned agent this step
  std::vector<bool> assigned_;  // assigned, or being assigned (then counted as waiting)
};

}  // namespace fleet_planner
