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
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "fleet_planner/runtime/random.h"
#include "fleet_planner/solvers/search/search_space.h"

namespace fleet_planner {

using Config = std::vector<StateId>;

/// At most kActions states of one agent (waiting and each action's result), kept in place: the
/// configuration step builds thousands of these a second and allocates none of them.
class StateChoices {
 public:
  void push(StateId s) { items_[size_++] = s; }
  int size() const { return size_; }
  StateId& operator[](int i) { return items_[i]; }
  const StateId* begin() const { return items_.data(); }
  const StateId* end() const { return items_.data() + size_; }

 private:
  std::array<StateId, kActions> items_{};
  int size_ = 0;
};

class LaPibt {
 public:
  /// remember_escapes: keep the answers of the escape searches (they depend only on the agents'
  /// states and the pusher's motion), which makes the same steps several times faster.
  LaPibt(const SearchSpace& space, std::uint64_t seed, bool remember_escapes = true);

  /// Next states of agent a from s: wait first, then every allowed action's result.
  StateChoices candidates(int a, StateId s) const;

  /// Fills `next` from `current`: agents in `fixed` (agent, next state) first, in that order,
  /// then the others in `order`. Returns false if the fixed moves cannot all be made.
  bool generate(const Config& current, const std::vector<std::pair<int, StateId>>& fixed,
                const std::vector<int>& order, Config& next);

  Rng& rng() { return rng_; }

 private:
  // Buckets of kBucketCells x kBucketCells map cells, each listing the agents that could sweep
  // one of its cells in the next step from their current state, built once per configuration:
  // fits() then checks the agents near a motion, not the whole fleet.
  void indexNear(const Config& current);
  // Calls f(b) once for every agent other than a that may sweep a cell of `set` at `origin`.
  template <class F>
  void forNear(int a, const CellSet& set, Cell origin, F&& f) const;
  // Bucket column (row) of map column x (row y), clamped to the map's buckets.
  int bucketX(int x) const { return std::clamp(x / kBucketCells, 0, bx_ - 1); }
  int bucketY(int y) const { return std::clamp(y / kBucketCells, 0, by_ - 1); }
  // a doing `action` from `from` meets no agent's sweep: the chosen one of an assigned agent,
  // at least the current footprint of the others. With `in_way`, the agents still to move that
  // it meets, in agent order.
  bool fits(int a, StateId from, Action action, const Config& current, std::vector<int>* in_way = nullptr) const;
  // Assigns agent a (and, through pushes, agents blocking it). `avoid`: the state the pusher
  // wants next (kNoState: none), `pusher` its agent; a must end clear of the pusher's sweep to
  // it. Returns false if a could not.
  bool assign(int a, const Config& current, Config& next, int pusher, StateId avoid);
  // First steps of a's shortest escapes (within kEscapeDepth steps and kEscapeStates states) to a state whose footprint
  // is clear of `sweep` at `origin`, best first.
  StateChoices escapeSteps(int a, StateId from, const CellSet& sweep, Cell origin) const;
  // escapeSteps of a from `from`, out of the way of `pusher` doing `action` from pusher_from,
  // remembered.
  StateChoices cachedEscape(int a, StateId from, int pusher, StateId pusher_from, Action action);
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
  // escapeSteps' scratch: the breadth-first queue and the stamps of the states it has seen.
  struct EscapeItem {
    StateId s;
    int first;  // index of the first step that led here
    int depth;
  };
  mutable std::vector<EscapeItem> escape_queue_;
  struct EscapeKey {
    std::uint64_t agent_state, pusher_motion;
    bool operator==(const EscapeKey& o) const { return agent_state == o.agent_state && pusher_motion == o.pusher_motion; }
  };
  struct EscapeHash {
    std::size_t operator()(const EscapeKey& k) const { return k.agent_state * 0x9e3779b97f4a7c15ULL ^ k.pusher_motion; }
  };
  static constexpr std::size_t kEscapeCache = 1 << 16;  // entries kept before starting afresh
  std::unordered_map<EscapeKey, StateChoices, EscapeHash> escapes_;

  mutable std::vector<std::uint32_t> seen_;
  mutable std::uint32_t seen_query_ = 0;
  std::vector<Action> chosen_;  // action of each assigned agent this step
  std::vector<bool> assigned_;  // assigned, or being assigned (then counted as waiting)
  bool remember_escapes_;
};

}  // namespace fleet_planner
