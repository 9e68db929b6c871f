#pragma once
// Internal helpers of the layered planner's merge and compression: the step a path takes at a
// time, whether two robots' steps meet, and bounding boxes that rule out most pairs cheaply.
#include <algorithm>
#include <cmath>

#include "fleet_planner/model/action.h"
#include "fleet_planner/model/collision.h"
#include "fleet_planner/model/footprint_cells.h"
#include "fleet_planner/model/plan.h"

namespace fleet_planner {
namespace path_steps {

struct Box {
  int x0, y0, x1, y1;
  bool meets(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};

/// A radius, in cells, that the footprint's cells never exceed (from the robot's cell).
inline int radiusOf(const FootprintCells& cells) { return cells.reach(); }

/// Bounding box of every cell a path (and its parked tail) can cover.
inline Box boxOf(const FootprintCells& cells, const Path& p) {
  const int r = radiusOf(cells);
  Box b{p[0].x, p[0].y, p[0].x, p[0].y};
  for (const GridPose& s : p) {
    b.x0 = std::min(b.x0, s.x);
    b.y0 = std::min(b.y0, s.y);
    b.x1 = std::max(b.x1, s.x);
    b.y1 = std::max(b.y1, s.y);
  }
  return {b.x0 - r, b.y0 - r, b.x1 + r, b.y1 + r};
}

/// The action a path takes from time t (Wait once it has ended).
inline Action actionAt(const Path& p, int t, const ActionModel& model) {
  if (t + 1 >= static_cast<int>(p.size())) return Action::Wait;
  return actionBetween(p[t], p[t + 1], model).value_or(Action::Wait);
}

/// Robot A's step from time ta and robot B's step from time tb sweep a common cell.
inline bool stepsMeet(const FootprintCells& A, const Path& a, int ta, const FootprintCells& B, const Path& b, int tb,
                      const ActionModel& model) {
  return sweepsOverlap(A, stateAt(a, ta), actionAt(a, ta, model), B, stateAt(b, tb), actionAt(b, tb, model));
}

}  // namespace path_steps
}  // namespace fleet_planner
