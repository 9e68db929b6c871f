#pragma once
/// The action model (paper: Preliminaries, "Subgraph of agent"): in one time step a robot waits,
/// moves forward along its heading, or rotates +-90 degrees in place. Moving backward is an
/// option, off by default to match the paper. There is no 180-degree turn.
///
/// A move advances `step` cells (the planning lattice: states every `step` map cells, step 1 is
/// the paper's model); its sweep is the footprint at every cell on the way, which is exact for a
/// straight translation along a grid axis. A plan may also hold shorter moves (1..step cells):
/// the motions that connect a pose off the lattice to it.
#include <cstdint>
#include <optional>

#include "fleet_planner/model/types.h"

namespace fleet_planner {

enum class Action : std::uint8_t { Wait = 0, Forward = 1, Backward = 2, RotateCcw = 3, RotateCw = 4 };
constexpr int kActions = 5;

struct ActionModel {
  bool allow_backward = false;  ///< also allow moving against the heading
  int step = 1;                 ///< cells a move advances: the lattice step (>= 1)
};

/// The pose after `action` (no map check); a move advances model.step cells.
GridPose applyAction(const GridPose& pose, Action action, const ActionModel& model = {});

/// Cells between two poses of one move (|dx| + |dy|); 0 for a wait or a rotation.
inline int moveLength(const GridPose& from, const GridPose& to) {
  return (from.x > to.x ? from.x - to.x : to.x - from.x) + (from.y > to.y ? from.y - to.y : to.y - from.y);
}

/// The action that turns `from` into `to` in one step under `model`, or nullopt if none does. A
/// move of 1..model.step cells along the heading is Forward (or Backward, when allowed).
std::optional<Action> actionBetween(const GridPose& from, const GridPose& to,
                                    const ActionModel& model);

/// "wait", "forward", "backward", "rotate+90", "rotate-90".
const char* actionName(Action action);

}  // namespace fleet_planner
