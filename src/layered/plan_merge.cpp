#include "fleet_planner/layered/plan_merge.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <set>
#include <unordered_map>

#include "fleet_planner/core/collision.h"
#include "path_steps.h"

namespace fleet_planner {

using path_steps::Box;
using path_steps::boxOf;
using path_steps::radiusOf;

namespace {

// The steps of a path before its end, bucketed by the cell they start from, with their actions:
// the steps of another robot that can meet a step at p are those in the buckets around p.
class StepIndex {
 public:
  StepIndex(const Path& p, const ActionModel& model, int bucket) : path_(p), bucket_(bucket) {
    for (int t = 0; t < static_cast<int>(p.size()); ++t) actions_.push_back(path_steps::actionAt(p, t, model));
    for (int t = 0; t + 1 < static_cast<int>(p.size()); ++t) buckets_[key(p[t].x / bucket_, p[t].y / bucket_)].push_back(t);
  }
  const GridPose& pose(int t) const { return path_[t]; }
  Action action(int t) const { return actions_[t]; }
  /// Calls f(t) for every indexed step starting within one bucket of (x, y), in no set order.
  template <class F>
  void near(int x, int y, F&& f) const {
    const int bx = x / bucket_, by = y / bucket_;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const auto it = buckets_.find(key(bx + dx, by + dy));
        if (it == buckets_.end()) continue;
        for (int t : it->second) f(t);
      }
    }
  }

 private:
  static std::uint64_t key(int bx, int by) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(bx)) << 32) | static_cast<std::uint32_t>(by);
  }
  const Path& path_;
  int bucket_;
  std::vector<Action> actions_;
  std::unordered_map<std::uint64_t, std::vector<int>> buckets_;
};

}  // namespace

int delayToFit(const FleetGraphs& graphs, const std::vector<Path>& merged, const std::vector<char>& done,
               const std::vector<int>& robots, std::vector<Path>& fresh) {
  if (robots.empty()) return 0;
  const ActionModel& model = graphs.graph(robots.front()).actionModel();
  // Steps of two robots can only meet when their cells are within both radii and a move of each
  // other: a bucket that wide puts such steps in neighbouring buckets.
  int radius = 0;
  for (int r : robots) radius = std::max(radius, radiusOf(graphs.cells(r)));
  for (int m = 0; m < static_cast<int>(merged.size()); ++m) {
    if (done[m]) radius = std::max(radius, radiusOf(graphs.cells(m)));
  }
  const int bucket = 2 * radius + 2;
  std::vector<std::unique_ptr<StepIndex>> index(merged.size());
  std::set<int> forbidden;
  int above = -1;  // every delay <= above is forbidden
  for (std::size_t k = 0; k < robots.size(); ++k) {
    // A robot with a path so far continues it: the new part starts once it has ended.
    if (done[robots[k]]) above = std::max(above, static_cast<int>(merged[robots[k]].size()) - 2);
  }
  for (std::size_t k = 0; k < robots.size(); ++k) {
    const FootprintCells& A = graphs.cells(robots[k]);
    const Path& a = fresh[k];
    const Box box_a = boxOf(A, a);
    const StepIndex steps_a(a, model, bucket);
    const int la = static_cast<int>(a.size()) - 1;  // a's last step; then parked
    for (int m = 0; m < static_cast<int>(merged.size()); ++m) {
      if (!done[m] || m == robots[k] || !box_a.meets(boxOf(graphs.cells(m), merged[m]))) continue;
      if (!index[m]) index[m] = std::make_unique<StepIndex>(merged[m], model, bucket);
      const StepIndex& b = *index[m];
      const FootprintCells& B = graphs.cells(m);
      // a's moving steps against b's moving steps. (b parked for good cannot meet a's step when
      // b's target was blocked for a, and no delay would fix it; the caller's validation of the
      // merged plan would report it.)
      for (int ta = 0; ta < la; ++ta) {
        const GridPose& pa = a[ta];
        b.near(pa.x, pa.y, [&](int tb) {
          if (tb >= ta && sweepsOverlap(A, pa, steps_a.action(ta), B, b.pose(tb), b.action(tb))) forbidden.insert(tb - ta);
        });
      }
      // a parked (from time la + d on) against b's step tb: forbidden when la + d <= tb.
      b.near(a[la].x, a[la].y, [&](int tb) {
        if (tb - la > above && sweepsOverlap(A, a[la], Action::Wait, B, b.pose(tb), b.action(tb))) above = tb - la;
      });
    }
  }
  int d = std::max(0, above + 1);
  while (forbidden.count(d)) ++d;
  for (Path& p : fresh) p.insert(p.begin(), static_cast<std::size_t>(d), p.front());
  return d;
}

void appendDelayed(std::vector<Path>& merged, int robot, Path delayed) {
  Path& path = merged[robot];
  if (path.empty()) {
    path = std::move(delayed);
    return;
  }
  const std::size_t from = path.size();  // delayed[from - 1] is where the path so far ends
  path.insert(path.end(), delayed.begin() + static_cast<std::ptrdiff_t>(from), delayed.end());
}

}  // namespace fleet_planner
