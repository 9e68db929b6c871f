#include "fleet_planner/model/action.h"

namespace fleet_planner {

GridPose applyAction(const GridPose& p, Action action) {
  const Cell step = kHeadingStep[p.heading];
  switch (action) {
    case Action::Wait:
      return p;
    case Action::Forward:
      return {p.x + step.x, p.y + step.y, p.heading};
    case Action::Backward:
      return {p.x - step.x, p.y - step.y, p.heading};
    case Action::RotateCcw:
      return {p.x, p.y, kRotateCcw[p.heading]};
    case Action::RotateCw:
      return {p.x, p.y, kRotateCw[p.heading]};
  }
  return p;
}

std::optional<Action> actionBetween(const GridPose& from, const GridPose& to,
                                    const ActionModel& model) {
  if (!validHeading(from.heading) || !validHeading(to.heading)) return std::nullopt;
  for (Action a : {Action::Wait, Action::Forward, Action::Backward, Action::RotateCcw,
                   Action::RotateCw}) {
    if (a == Action::Backward && !model.allow_backward) continue;
    if (applyAction(from, a) == to) return a;
  }
  return std::nullopt;
}

const char* actionName(Action action) {
  switch (action) {
    case Action::Wait:
      return "wait";
    case Action::Forward:
      return "forward";
    case Action::Backward:
      return "backward";
    case Action::RotateCcw:
      return "rotate+90";
    case Action::RotateCw:
      return "rotate-90";
  }
  return "?";
}

}  // namespace fleet_planner
