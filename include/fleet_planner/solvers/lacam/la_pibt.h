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
/// drive away), while it waits; the way opens in the next steps. Waiting always fits, so a
/// configuration is produced unless the fixed moves clash.
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "fleet_planner/runtime/random.h"
#include "fleet_planner/solvers/search/search_space.h"

namespace fleet_planner {

using Config = std::vector<StateId>;

/// At most kActions states of one agent (waiting and each action's result), each with the
/// action that leads there, kept in place: the configuration step builds thousands of these a
/// second and allocates none of them.
class StateChoices {
 public:
  void push(StateId s, Action action) {
    states_[size_] = s;
    actions_[size_++] = action;
  }
  int size() const { return size_; }
  StateId operator[](int i) const { return states_[i]; }
  Action action(int i) const { return actions_[i]; }
  void swap(int i, int j) {
    std::swap(states_[i], states_[j]);
    std::swap(actions_[i], actions_[j]);
  }

 private:
  std::array<StateId, kActions> states_{};
  std::array<Action, kActions> actions_{};
  int size_ = 0;
};

class LaPibt {
 public:
  /// remember_escapes: keep the answers of the escape searches (they depend only on the agents'
  /// states and the pusher's motion), which makes the same steps several times faster.
  LaPibt(const SearchSpace& space, std::uint64_t seed, bool remember_escapes = true);

  /// Next states of agent a from s: wait first, then every allowed action's result (with their
  /// distances to a's target in candidate_distances_[a]). Remembered per agent for its last
  /// state, valid until a's next call: agents of a packed fleet often stand still from one
  /// configuration to the next, and the graph's and distance table's reads behind an answer are
  /// cache misses.
  const StateChoices& candidates(int a, StateId s);

  /// Fills `next` from `current`: agents in `fixed` (agent, next state) first, in that order,
  /// then the others in `order`. Returns false if the fixed moves cannot all be made.
  bool generate(const Config& current, const std::vector<std::pair<int, StateId>>& fixed,
                const std::vector<int>& order, Config& next);

  Rng& rng() { return rng_; }

 private:
  // Marks the cells of `set` at pose p as claimed by agent a this step.
  void claim(int a, const CellSet& set, const GridPose& p);
  // Claims agent a's motion `action` from where it stands: its sweep.
  void claimMotion(int a, Action action);
  // Starts a step: every agent claims its current footprint (moved from the last step's).
  void claimFootprints(const Config& current);
  // a doing `action` from where it stands meets no agent's claim: the sweep of an assigned
  // agent's motion, the current footprint of the others. With `in_way`, the agents still to
  // move that it meets, in agent order, appended to it.
  bool fits(int a, Action action, std::vector<int>* in_way = nullptr) const;
  // Assigns agent a (and, through pushes, agents blocking it). `pusher`: the agent whose motion
  // `pushing` (from where it stands) a blocks (-1: none); a must end clear of that motion's
  // sweep. Returns false if a could not.
  bool assign(int a, const Config& current, Config& next, int pusher, Action pushing);
  // First steps of a's shortest escapes (within kEscapeDepth steps and kEscapeStates states) to a
  // state whose footprint is clear of `sweep` at `origin`, best first.
  StateChoices escapeSteps(int a, StateId from, const CellSet& sweep, Cell origin) const;
  // escapeSteps of a from `from`, out of the way of `pusher` doing `action` from where it
  // stands, remembered.
  StateChoices cachedEscape(int a, StateId from, int pusher, Action action);
  static constexpr int kEscapeDepth = 8;
  static constexpr std::size_t kEscapeStates = 4096;  // bound on one escape search

  const SearchSpace& space_;
  Rng rng_;
  // Which agent claims each map cell this step (-1: none): the footprint of the agent standing
  // there in the configuration, which every action of that agent sweeps, or the sweep of an
  // assigned agent's motion outside its footprint. Claims never overlap (a motion is taken only
  // where it fits), so a cell has one owner, and fits() reads the cells of one sweep instead
  // of comparing agents. Four bytes a cell keep the map's claims in the nearest caches.
  int width_ = 0, height_ = 0;
  std::vector<std::int32_t> owner_;
  std::vector<std::size_t> swept_;  // the cells of this step's motions, freed at the next step
  Config placed_;  // the states whose footprints owner_ holds
  std::vector<GridPose> at_;  // their poses: every claim this step starts from them
  // Per agent, heading and action: the cells fits() reads (see the constructor).
  using Ahead = std::array<std::array<CellSet, kActions>, kHeadings>;
  std::vector<std::shared_ptr<const Ahead>> ahead_;
  // Per agent, heading and action: the cells its footprint leaves and the cells it enters,
  // relative to the pose before the action, so that claimFootprints moves a footprint one step
  // by the cells that change (most of a large body stays where it was); and the cells of the
  // action's sweep outside that footprint, which are all that a motion claims (the footprint's
  // cells already name the agent).
  struct BodyStep {
    CellSet leaves, enters, sweeps;
  };
  using BodySteps = std::array<std::array<BodyStep, kActions>, kHeadings>;
  std::vector<std::shared_ptr<const BodySteps>> body_steps_;
  // The action taking `from` to `to` in one whole step of the agents' action model, -1 if
  // none. Not actionBetween (action.h): that one also takes the shorter moves of lattice
  // connections, for which the body steps' cells do not hold, and it is called across
  // translation units on the hot path of every configuration.
  int oneStep(const GridPose& from, const GridPose& to) const;
  // Per heading and action: the pose the action leads to from (0, 0) at that heading.
  std::array<std::array<GridPose, kActions>, kHeadings> step_to_{};
  mutable std::vector<std::uint32_t> seen_agent_;  // dedup of fits()' agents in the way
  mutable std::uint32_t agent_query_ = 0;
  // escapeSteps' scratch: the breadth-first queue and the stamps of the states it has seen.
  struct EscapeItem {
    StateId s;
    int first;  // index of the first step that led here
    int depth;
  };
  mutable std::vector<EscapeItem> escape_queue_;
  // Remembered escapes, direct-mapped: a key's one slot holds the last answer that hashed
  // there (a miss recomputes and replaces it), so memory stays fixed and nothing is cleared.
  struct Escape {
    std::uint64_t agent_state = ~std::uint64_t{0};  // (agent << 32) | state; all ones: empty
    std::uint64_t pusher_motion = 0;                // (pusher << 35) | (action << 32) | state
    StateChoices steps;
  };
  static constexpr std::size_t kEscapeSlots = 1 << 16;  // at most
  std::vector<Escape> escapes_;

  mutable std::vector<std::uint32_t> seen_;
  mutable std::uint32_t seen_query_ = 0;
  std::vector<StateId> candidates_at_;       // per agent: the state of candidates_[a]
  std::vector<StateChoices> candidates_;     // per agent: its candidates() at candidates_at_[a]
  std::vector<std::array<int, kActions>> candidate_distances_;  // and their distances to target
  std::vector<char> assigned_;  // assigned, or being assigned (then counted as waiting)
  std::vector<int> in_way_;     // assign()'s agents in the way, a stack shared by nested pushes
  bool remember_escapes_;
};

}  // namespace fleet_planner
