#include "fleet_planner/layered/plan_merge.h"

#include <algorithm>
#include <set>

#include "path_steps.h"

namespace fleet_planner {

using path_steps::boxOf;
using path_steps::Box;
using path_steps::stepsMeet;

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
