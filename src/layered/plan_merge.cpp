#include "fleet_planner/layered/plan_merge.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "fleet_planner/core/action.h"
#include "fleet_planner/core/collision.h"

namespace fleet_planner {

namespace {

struct Box {
  int x0, y0, x1, y1;
  bool meets(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};

// Bounding box of every cell a path (and its parked tail) can cover.
Box boxOf(const FootprintCells& cells, const Path& p) {
  const int r = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(cells.maxNormSq())))) + 1;
  Box b{p[0].x, p[0].y, p[0].x, p[0].y};
  for (const GridPose& s : p) {
    b.x0 = std::min(b.x0, s.x);
    b.y0 = std::min(b.y0, s.y);
    b.x1 = std::max(b.x1, s.x);
    b.y1 = std::max(b.y1, s.y);
  }
  return {b.x0 - r, b.y0 - r, b.x1 + r, b.y1 + r};
}

Action actionAt(const Path& p, int t, const ActionModel& model) {
  if (t + 1 >= static_cast<int>(p.size())) return Action::Wait;
  return actionBetween(p[t], p[t + 1], model).value_or(Action::Wait);
}

bool stepsMeet(const FootprintCells& A, const Path& a, int ta, const FootprintCells& B, const Path& b, int tb,
               const ActionModel& model) {
  return sweepsOverlap(A, stateAt(a, ta), actionAt(a, ta, model), B, stateAt(b, tb), actionAt(b, tb, model));
}

}  // namespace

int delayToFit(const FleetGraphs& graphs, const std::vector<Path>& merged, const std::vector<char>& done,
               const std::vector<int>& robots, std::vector<Path>& fresh) {
  if (robots.empty()) return 0;
  const ActionModel& model = graphs.graph(robots.front()).actionModel();
  std::set<int> forbidden;
  int above = -1;  // every delay <= above is forbidden
  for (std::size_t k = 0; k < robots.size(); ++k) {
    const FootprintCells& A = graphs.cells(robots[k]);
    const Path& a = fresh[k];
    const Box box_a = boxOf(A, a);
    const int la = static_cast<int>(a.size()) - 1;  // a's last step; then parked
    for (int m = 0; m < static_cast<int>(merged.size()); ++m) {
      if (!done[m] || !box_a.meets(boxOf(graphs.cells(m), merged[m]))) continue;
      const FootprintCells& B = graphs.cells(m);
      const Path& b = merged[m];
      const int lb = static_cast<int>(b.size()) - 1;
      for (int tb = 0; tb <= lb; ++tb) {
        // a's moving steps against b's steps (tb = lb: b parked, the same for every later tb).
        for (int ta = 0; ta < la; ++ta) {
          if (!stepsMeet(A, a, ta, B, b, tb, model)) continue;
          if (tb < lb) {
            if (tb - ta >= 0) forbidden.insert(tb - ta);
          } else {
            // b parked for good meets a's step: cannot happen when b's target was blocked for a,
            // and no delay would fix it; the caller's validation of the merged plan reports it.
            continue;
          }
        }
        // a parked (from time la + d on) against b's step tb: forbidden when la + d <= tb.
        if (tb < lb && stepsMeet(A, a, la, B, b, tb, model)) above = std::max(above, tb - la);
      }
    }
  }
  int d = std::max(0, above + 1);
  while (forbidden.count(d)) ++d;
  for (Path& p : fresh) p.insert(p.begin(), static_cast<std::size_t>(d), p.front());
  return d;
}

}  // namespace fleet_planner
