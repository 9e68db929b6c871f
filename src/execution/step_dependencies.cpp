// Execution dependencies of a plan (MAPF-POST / action dependency graph); see step_dependencies.h.
#include "fleet_planner/execution/step_dependencies.h"

#include <algorithm>
#include <climits>

namespace fleet_planner {

namespace {

// A stretch of a robot's plan on one set of cells: one move, a run of waits on one pose, or the
// rest after its last state (last = INT_MAX).
struct Stretch {
  int first = 0;
  int last = 0;
  PlacedCells cells;
};

std::vector<Stretch> stretchesOf(const PlanCells& cells, int robot) {
  std::vector<Stretch> out;
  const int end = cells.lastState(robot);
  for (int t = std::min(cells.from(), end); t < end; ++t) {
    const PlacedCells c = cells.during(robot, t);
    const bool extends = !out.empty() && !cells.isMove(robot, t) && !cells.isMove(robot, t - 1) &&
                         out.back().cells.cells == c.cells && out.back().cells.at == c.at;
    if (extends) {
      out.back().last = t;
    } else {
      out.push_back({t, t, c});
    }
  }
  out.push_back({end, INT_MAX, cells.atRest(robot, end)});
  return out;
}

// For every cell of the plan's bounding box, the robots that covered it so far, each with the last
// step it did so: a list per cell, linked through one pool.
class CellHistory {
 public:
  explicit CellHistory(const std::vector<std::vector<Stretch>>& stretches) {
    bool any = false;
    int x1 = 0, y1 = 0;
    for (const auto& list : stretches) {
      for (const Stretch& s : list) {
        const CellSet& c = *s.cells.cells;
        if (c.empty()) continue;
        const int ax = s.cells.at.x + c.minX(), ay = s.cells.at.y + c.minY();
        const int bx = s.cells.at.x + c.maxX(), by = s.cells.at.y + c.maxY();
        x0_ = any ? std::min(x0_, ax) : ax;
        y0_ = any ? std::min(y0_, ay) : ay;
        x1 = any ? std::max(x1, bx) : bx;
        y1 = any ? std::max(y1, by) : by;
        any = true;
      }
    }
    width_ = any ? x1 - x0_ + 1 : 0;
    head_.assign(any ? static_cast<std::size_t>(width_) * (y1 - y0_ + 1) : 0, -1);
  }

  // Robot `robot` covers `cells` up to step `last` (later calls for a robot: later stretches).
  void record(int robot, const PlacedCells& cells, int last) {
    forEachCell(cells, [&](std::size_t cell) {
      for (int e = head_[cell]; e >= 0; e = entries_[e].next) {
        if (entries_[e].robot == robot) {
          entries_[e].last = last;
          return;
        }
      }
      entries_.push_back({robot, last, head_[cell]});
      head_[cell] = static_cast<int>(entries_.size()) - 1;
    });
  }

  // Calls f(robot, last) for every robot recorded on any of `cells` (once per cell it is on).
  template <class F>
  void visit(const PlacedCells& cells, F f) const {
    forEachCell(cells, [&](std::size_t cell) {
      for (int e = head_[cell]; e >= 0; e = entries_[e].next) f(entries_[e].robot, entries_[e].last);
    });
  }

 private:
  template <class F>
  void forEachCell(const PlacedCells& cells, F f) const {
    for (const CellSet::Run& run : cells.cells->runs()) {
      const std::size_t row = static_cast<std::size_t>(cells.at.y + run.dy - y0_) * width_;
      for (int x = cells.at.x + run.x0; x <= cells.at.x + run.x1; ++x) f(row + (x - x0_));
    }
  }

  struct Entry {
    int robot;
    int last;
    int next;
  };
  int x0_ = 0, y0_ = 0, width_ = 0;
  std::vector<int> head_;
  std::vector<Entry> entries_;
};

}  // namespace

std::size_t StepDependencies::count() const {
  std::size_t n = 0;
  for (const auto& robot : before)
    for (const auto& step : robot) n += step.size();
  return n;
}

StepDependencies buildStepDependencies(const PlanCells& cells) {
  const int n = cells.robots();
  std::vector<std::vector<Stretch>> stretches(n);
  int horizon = 0;
  StepDependencies deps;
  deps.before.resize(n);
  for (int i = 0; i < n; ++i) {
    stretches[i] = stretchesOf(cells, i);
    horizon = std::max(horizon, cells.lastState(i));
    deps.before[i].resize(cells.lastState(i));
  }
  CellHistory history(stretches);
  std::vector<std::size_t> next(n, 0);   // each robot's first stretch not yet recorded
  std::vector<int> required(static_cast<std::size_t>(n) * n, 0);  // [i * n + j]: j's state i needs so far
  std::vector<int> latest(n, -1);        // per query: the last step each robot overlaps
  std::vector<int> touched;

  const int from = std::min(cells.from(), horizon);
  for (int j = 0; j < n; ++j) {  // stretches that end before `from` (only the rest after a path's end can)
    for (; next[j] < stretches[j].size() && stretches[j][next[j]].first < from; ++next[j]) {
      history.record(j, stretches[j][next[j]].cells, stretches[j][next[j]].last);
    }
  }
  for (int t = from; t <= horizon; ++t) {
    // The moves at step t look back at steps < t: the history holds exactly those so far.
    for (int i = 0; i < n; ++i) {
      if (t >= cells.lastState(i) || !cells.isMove(i, t)) continue;
      history.visit(cells.during(i, t), [&](int j, int last) {
        if (j == i) return;
        if (latest[j] < 0) touched.push_back(j);
        latest[j] = std::max(latest[j], std::min(last, t - 1));
      });
      std::sort(touched.begin(), touched.end());
      for (int j : touched) {
        int& have = required[static_cast<std::size_t>(i) * n + j];
        if (latest[j] + 1 > have) {
          have = latest[j] + 1;
          deps.before[i][t].push_back({j, have});
        }
        latest[j] = -1;
      }
      touched.clear();
    }
    for (int j = 0; j < n; ++j) {
      for (; next[j] < stretches[j].size() && stretches[j][next[j]].first == t; ++next[j]) {
        history.record(j, stretches[j][next[j]].cells, stretches[j][next[j]].last);
      }
    }
  }
  return deps;
}

StepDependencies buildStepDependencies(const Instance& instance, const Plan& plan, const ActionModel& model,
                                       int from) {
  return buildStepDependencies(PlanCells(instance, plan, model, from));
}

}  // namespace fleet_planner
