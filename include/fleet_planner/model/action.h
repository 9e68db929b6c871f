#pragma once
/// The action model (paper: Preliminaries, "Subgraph of agent"): in one time step a robot waits,
/// moves one cell forward along its heading, or rotates +-90 degrees in place. Moving one cell
/// backward is an option, off by default to match the paper. There is no 180-degree turn.
#include <cstdint>
#include <optional>

#include "fleet_planner/model/types.h"

namespace fleet_planner {

enum class Action : std::uint8_t { Wait = 0, Forward = 1, Backward = 2, RotateCcw = 3, RotateCw = 4 };
constexpr int kActions = 5;

struct ActionModel {
  bool allow_backward = false;  ///< also allow moving one cell against the heading
};

/// The pose after `action` (no map check).
GridPose applyAction(const GridPose& pose, Action action);

/// The action that turns `from` into `to` in one step under `model`, or nullopt if none does.
std::optional<Action> actionBetween(const GridPose& from, const GridPose& to,
                                    const ActionModel& model);

/// "wait", "forward", "backward", "rotate+90", "rotate-90".
const char* actionName(Action action);

}  // namespace fleet_planner
