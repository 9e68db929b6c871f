// Plan compression; see plan_compression.h.
#include "fleet_planner/layered/plan_compression.h"

#include <algorithm>
#include <chrono>

#include "fleet_planner/execution/earliest_schedule.h"

#include "path_steps.h"

namespace fleet_planner {

namespace {

using path_steps::Box;
using path_steps::stepsMeet;

class Compressor {
 public:
  Compressor(const FleetGraphs& graphs, std::vector<Path>& paths) : graphs_(graphs), paths_(paths) {
    const int n = static_cast<int>(paths_.size());
    if (n > 0) model_ = graphs_.graph(0).actionModel();
    // Dropping waits keeps every path's set of states, so the boxes, and the pairs that can
    // meet at all, never change.
    std::vector<Box> boxes;
    for (int i = 0; i < n; ++i) {
      boxes.push_back(path_steps::boxOf(graphs_.cells(i), paths_[i]));
      reach_.push_back(path_steps::radiusOf(graphs_.cells(i)) + model_.step);
    }
    near_.resize(n);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        if (j != i && boxes[i].meets(boxes[j])) near_[i].push_back(j);
      }
    }
  }

  /// One pass over the robots; returns the number of waits dropped.
  long long pass(const Deadline& deadline) {
    long long removed = 0;
    for (std::size_t i = 0; i < paths_.size() && !deadline.expired(); ++i) removed += compressRobot(static_cast<int>(i));
    return removed;
  }

 private:
  long long compressRobot(int i) {
    Path& p = paths_[i];
    long long removed = 0;
    // A robot parks at its last state, so trailing waits mean nothing.
    while (p.size() > 1 && p[p.size() - 2] == p.back()) p.pop_back();
    std::size_t t = 0;
    while (t + 1 < p.size()) {
      if (!(p[t] == p[t + 1])) {
        ++t;
        continue;
      }
      std::size_t run = 1;  // waits at steps t .. t + run - 1
      while (t + run + 1 < p.size() && p[t + run] == p[t + run + 1]) ++run;
      bool moved = false;
      for (std::size_t drop : {run, std::size_t{1}}) {
        Path shifted(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(t) + 1);
        shifted.insert(shifted.end(), p.begin() + static_cast<std::ptrdiff_t>(t + drop) + 1, p.end());
        if (fits(i, shifted, static_cast<int>(t))) {
          p = std::move(shifted);
          removed += static_cast<long long>(drop);
          moved = true;
          break;
        }
        if (run == 1) break;
      }
      if (!moved) t += run;  // its next action cannot come earlier (yet)
    }
    return removed;
  }

  /// Robot i following `p` from time t0 on meets no other robot (the states before t0 are
  /// unchanged). At the last time checked both robots are parked, so their final footprints
  /// are compared too. A step sweeps cells within the robot's radius plus one move of its
  /// state, so the steps at which two robots stand farther apart than both are skipped.
  bool fits(int i, const Path& p, int t0) const {
    const FootprintCells& A = graphs_.cells(i);
    for (int j : near_[i]) {
      const Path& q = paths_[j];
      const FootprintCells& B = graphs_.cells(j);
      const int reach = reach_[i] + reach_[j];
      const int last = std::max(t0, static_cast<int>(std::max(p.size(), q.size())) - 1);
      for (int t = t0; t <= last; ++t) {
        const GridPose& a = stateAt(p, t);
        const GridPose& b = stateAt(q, t);
        if (fartherApart(a, b, reach)) continue;
        if (stepsMeet(A, p, t, B, q, t, model_)) return false;
      }
    }
    return true;
  }

  const FleetGraphs& graphs_;
  std::vector<Path>& paths_;
  ActionModel model_{};
  std::vector<std::vector<int>> near_;
  std::vector<int> reach_;  // per robot: its radius plus one move, in cells
};

}  // namespace

CompressionStats compressPlan(const Instance& instance, const FleetGraphs& graphs, std::vector<Path>& paths,
                              const Deadline& deadline) {
  const auto start = std::chrono::steady_clock::now();
  CompressionStats stats;
  if (!paths.empty() && !deadline.expired()) {
    Plan plan;
    plan.paths = std::move(paths);
    stats.waits_removed = retimeToEarliest(instance, plan, graphs.graph(0).actionModel());
    paths = std::move(plan.paths);
  }
  // Then one robot at a time, which may also drop a wait by letting two steps swap their order.
  Compressor compressor(graphs, paths);
  while (!deadline.expired()) {
    ++stats.passes;
    const long long removed = compressor.pass(deadline);
    stats.waits_removed += removed;
    if (removed == 0) break;
  }
  stats.deadline_hit = deadline.expired();
  stats.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace fleet_planner
