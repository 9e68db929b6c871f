#include "fleet_planner/layered/plan_merge.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "fleet_planner/model/collision.h"
#include "path_steps.h"

namespace fleet_planner {

using path_steps::Box;
using path_steps::boxOf;
using path_steps::radiusOf;

namespace {

// The steps of a path before its end, bucketed by the cell they start from, as runs: a wait that
// lasts many steps (a delayed start, a robot waiting for another) is one run, since every step of
// it sweeps the same cells. The runs of another robot that can meet a step at p are those in the
// buckets around p.
class StepIndex {
 public:
  struct Run {
    int first, last;  // steps first..last, all from the same pose with the same action
  };

  StepIndex(const Path& p, const ActionModel& model, int bucket) : path_(p), bucket_(bucket) {
    const int steps = static_cast<int>(p.size()) - 1;
    for (int t = 0; t < steps;) {
      const Action action = path_steps::actionAt(p, t, model);
      int last = t;
      if (action == Action::Wait && p[t + 1] == p[t]) {
        while (last + 1 < steps && p[last + 2] == p[t]) ++last;
      }
      runs_.push_back({t, last});
      actions_.push_back(action);
      buckets_[key(p[t].x / bucket_, p[t].y / bucket_)].push_back(static_cast<int>(runs_.size()) - 1);
      t = last + 1;
    }
  }
  const std::vector<Run>& runs() const { return runs_; }
  const GridPose& pose(int run) const { return path_[runs_[run].first]; }
  Action action(int run) const { return actions_[run]; }
  /// Calls f(run) for every run starting within one bucket of (x, y), in no set order.
  template <class F>
  void near(int x, int y, F&& f) const {
    const int bx = x / bucket_, by = y / bucket_;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const auto it = buckets_.find(key(bx + dx, by + dy));
        if (it == buckets_.end()) continue;
        for (int r : it->second) f(r);
      }
    }
  }

 private:
  static std::uint64_t key(int bx, int by) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(bx)) << 32) | static_cast<std::uint32_t>(by);
  }
  const Path& path_;
  int bucket_;
  std::vector<Run> runs_;
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
  std::vector<Box> boxes(merged.size());
  for (int m = 0; m < static_cast<int>(merged.size()); ++m) {
    if (done[m]) boxes[m] = boxOf(graphs.cells(m), merged[m]);
  }
  std::vector<std::pair<int, int>> forbidden;  // delay intervals [lo, hi]
  int above = -1;                              // every delay <= above is forbidden
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
      if (!done[m] || m == robots[k] || !box_a.meets(boxes[m])) continue;
      if (!index[m]) index[m] = std::make_unique<StepIndex>(merged[m], model, bucket);
      const StepIndex& b = *index[m];
      const FootprintCells& B = graphs.cells(m);
      // a's moving steps against b's moving steps: a's steps sa.first..sa.last and b's
      // sb.first..sb.last forbid the delays tb - ta >= 0 between them. (b parked for good cannot
      // meet a's step when b's target was blocked for a, and no delay would fix it; the caller's
      // validation of the merged plan would report it.)
      for (int ra = 0; ra < static_cast<int>(steps_a.runs().size()); ++ra) {
        const StepIndex::Run sa = steps_a.runs()[ra];
        const GridPose& pa = steps_a.pose(ra);
        b.near(pa.x, pa.y, [&](int rb) {
          const StepIndex::Run sb = b.runs()[rb];
          if (sb.last < sa.first) return;
          if (sweepsOverlap(A, pa, steps_a.action(ra), B, b.pose(rb), b.action(rb)))
            forbidden.push_back({std::max(0, sb.first - sa.last), sb.last - sa.first});
        });
      }
      // a parked (from time la + d on) against b's step tb: forbidden when la + d <= tb.
      b.near(a[la].x, a[la].y, [&](int rb) {
        const int last = b.runs()[rb].last;
        if (last - la > above && sweepsOverlap(A, a[la], Action::Wait, B, b.pose(rb), b.action(rb))) above = last - la;
      });
    }
  }
  int d = std::max(0, above + 1);
  std::sort(forbidden.begin(), forbidden.end());
  for (const auto& [lo, hi] : forbidden) {
    if (lo <= d && d <= hi) d = hi + 1;
  }
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
