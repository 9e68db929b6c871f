#pragma once
/// A robot's state graph G_i = (V_i, E_i) (paper: Preliminaries, "Subgraph of agent"): every
/// state whose footprint is obstacle-free and every action whose swept cells are obstacle-free.
/// One graph serves every robot whose footprint covers the same cells.
///
/// Storage is one byte per state id (cell * 4 + heading) over the whole grid: bit 0 = state
/// valid, bit 1 + a = action `a` leads to a valid state through free cells. A move advances
/// ActionModel::step cells, so the states reachable from a pose form its lattice: every `step`
/// cells along each axis through it.
#include <cstdint>
#include <memory>
#include <vector>

#include "fleet_planner/model/action.h"
#include "fleet_planner/model/footprint_cells.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/obstacle_index.h"

namespace fleet_planner {

class StateGraph {
 public:
  StateGraph(const GridMap& map, const ObstacleIndex& obstacles,
             std::shared_ptr<const FootprintCells> cells, ActionModel model = {});

  int width() const { return width_; }
  int height() const { return height_; }
  /// Number of state ids, valid or not (4 * cells).
  int stateIdCount() const { return static_cast<int>(flags_.size()); }
  int numValidStates() const { return num_valid_; }
  long long numEdges() const { return num_edges_; }
  const FootprintCells& cells() const { return *cells_; }
  const ActionModel& actionModel() const { return model_; }

  /// The state id of a pose, or kNoState if the pose is off the map or has a bad heading.
  StateId id(const GridPose& p) const {
    if (p.x < 0 || p.y < 0 || p.x >= width_ || p.y >= height_ || !validHeading(p.heading)) return kNoState;
    return (p.y * width_ + p.x) * kHeadings + p.heading;
  }
  GridPose pose(StateId s) const {
    if (s < 0) {  // not a state: the plain arithmetic, as for any id
      const int cell = s / kHeadings;
      return {cell % width_, cell / width_, s % kHeadings};
    }
    // The row by a multiplication and a shift instead of a division (Granlund and Montgomery,
    // 1994: exact for every cell index below 2^29, i.e. every state id): the searches' hottest
    // loops ask for poses, and a division costs them tens of cycles each time.
    const std::uint64_t cell = static_cast<std::uint32_t>(s) >> 2;
    const auto row = static_cast<int>((cell * row_magic_) >> row_shift_);
    return {static_cast<int>(cell) - row * width_, row, s & (kHeadings - 1)};
  }
  bool valid(StateId s) const { return s >= 0 && s < stateIdCount() && (flags_[s] & 1u); }
  /// The action's edge exists (wait: the state is valid).
  bool allows(StateId s, Action a) const {
    return valid(s) && (a == Action::Wait || (flags_[s] >> (static_cast<int>(a))) & 1u);
  }
  /// The state `a` leads to (no validity check; the id is off-grid-safe only if allows()).
  StateId next(StateId s, Action a) const;

  /// Calls f(action, next_state) for every edge out of s, wait excluded.
  template <class F>
  void forEachSuccessor(StateId s, F&& f) const {
    for (int a = 1; a < kActions; ++a) {
      if (allows(s, static_cast<Action>(a))) f(static_cast<Action>(a), next(s, static_cast<Action>(a)));
    }
  }
  /// Calls f(action, previous_state) for every edge into s, wait excluded.
  template <class F>
  void forEachPredecessor(StateId s, F&& f) const;

  std::size_t memoryBytes() const { return flags_.capacity(); }

 private:
  int width_;
  int height_;
  // pose()'s division by width_: cell / width_ == (cell * row_magic_) >> row_shift_, with
  // row_shift_ = 29 + ceil(log2 width_) and row_magic_ = ceil(2^row_shift_ / width_).
  int row_shift_;
  std::uint64_t row_magic_;
  std::shared_ptr<const FootprintCells> cells_;
  ActionModel model_;
  std::vector<std::uint8_t> flags_;
  int num_valid_ = 0;
  long long num_edges_ = 0;
};

inline StateId StateGraph::next(StateId s, Action a) const {
  const int h = s % kHeadings;
  const Cell step{kHeadingStep[h].x * model_.step, kHeadingStep[h].y * model_.step};
  switch (a) {
    case Action::Wait:
      return s;
    case Action::Forward:
      return s + (step.y * width_ + step.x) * kHeadings;
    case Action::Backward:
      return s - (step.y * width_ + step.x) * kHeadings;
    case Action::RotateCcw:
      return s - h + kRotateCcw[h];
    case Action::RotateCw:
      return s - h + kRotateCw[h];
  }
  return s;
}

template <class F>
void StateGraph::forEachPredecessor(StateId s, F&& f) const {
  const GridPose p = pose(s);
  const Cell step{kHeadingStep[p.heading].x * model_.step, kHeadingStep[p.heading].y * model_.step};
  const StateId back = id({p.x - step.x, p.y - step.y, p.heading});
  if (back != kNoState && allows(back, Action::Forward)) f(Action::Forward, back);
  const StateId ahead = id({p.x + step.x, p.y + step.y, p.heading});
  if (ahead != kNoState && allows(ahead, Action::Backward)) f(Action::Backward, ahead);
  const StateId from_cw = s - p.heading + kRotateCw[p.heading];   // rotating ccw from here gives s
  if (allows(from_cw, Action::RotateCcw)) f(Action::RotateCcw, from_cw);
  const StateId from_ccw = s - p.heading + kRotateCcw[p.heading];  // rotating cw from here gives s
  if (allows(from_ccw, Action::RotateCw)) f(Action::RotateCw, from_ccw);
}

}  // namespace fleet_planner
