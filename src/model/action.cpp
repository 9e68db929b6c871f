#include "fleet_planner/model/action.h"

namespace fleet_planner {

GridPose applyAction(const GridPose& p, Action action, const ActionModel& model) {
  const Cell step{kHeadingStep[p.heading].x * model.step, kHeadingStep[p.heading].y * model.step};
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
  if (from == to) return Action::Wait;
  if (from.x == to.x && from.y == to.y) {
    for (Action a : {Action::RotateCcw, Action::RotateCw}) {
      if (applyAction(from, a) == to) return a;
    }
    return std::nullopt;
  }
  // A move: the same heading, 1..step cells along it.
  const int length = moveLength(from, to);
  if (from.heading != to.heading || length > model.step) return std::nullopt;
  const ActionModel exact{model.allow_backward, length};
  if (applyAction(from, Action::Forward, exact) == to) return Action::Forward;
  if (model.allow_backward && applyAction(from, Action::Backward, exact) == to) return Action::Backward;
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
