#include "fleet_planner/solvers/search/reservation_table.h"

#include <algorithm>

#include "fleet_planner/model/action.h"
#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

ReservationTable::ReservationTable(int width, int height, const std::vector<MovingObstacle>& moving,
                                   const FleetGraphs& graphs, const ActionModel& model)
    : width_(width), height_(height) {
  struct Entry {
    std::int32_t cell;
    Interval interval;
  };
  std::vector<Entry> entries;
  auto reserve = [&](const CellSet& set, const GridPose& at, int first, int last) {
    for (const auto& run : set.runs()) {
      const int y = at.y + run.dy;
      for (int x = at.x + run.x0; x <= at.x + run.x1; ++x) {
        if (x < 0 || y < 0 || x >= width_ || y >= height_) continue;
        entries.push_back({y * width_ + x, {first, last}});
      }
    }
  };
  for (const MovingObstacle& m : moving) {
    if (m.path.empty()) throw InvalidInput("moving obstacle of robot index " + std::to_string(m.robot) + " has an empty path");
    const FootprintCells& cells = graphs.cells(m.robot);
    for (std::size_t t = 0; t + 1 < m.path.size(); ++t) {
      const auto action = actionBetween(m.path[t], m.path[t + 1], model);
      if (!action) {
        throw InvalidInput("moving obstacle of robot index " + std::to_string(m.robot) + " makes an illegal step at t=" +
                           std::to_string(t));
      }
      // A run of waits is one reservation: merged plans wait for thousands of steps, and one
      // entry per cell and step made building the table most of the refinement's time.
      std::size_t last = t;
      if (*action == Action::Wait) {
        while (last + 2 < m.path.size() && m.path[last + 2] == m.path[t]) ++last;
      }
      reserve(cells.swept(m.path[t].heading, *action), m.path[t], static_cast<int>(t), static_cast<int>(last));
      t = last;
    }
    const int end = static_cast<int>(m.path.size()) - 1;
    reserve(cells.body(m.path.back().heading), m.path.back(), end, kForever);
    last_change_ = std::max(last_change_, end);
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.cell != b.cell ? a.cell < b.cell : a.interval.first < b.interval.first;
  });
  offsets_.assign(static_cast<std::size_t>(width_) * height_ + 1, 0);
  for (std::size_t i = 0; i < entries.size();) {
    const std::int32_t cell = entries[i].cell;
    Interval current = entries[i].interval;
    for (++i; i < entries.size() && entries[i].cell == cell; ++i) {
      const Interval& next = entries[i].interval;
      if (current.last != kForever && next.first <= current.last + 1) {
        current.last = std::max(current.last, next.last);
      } else if (current.last == kForever) {
        continue;  // already held forever
      } else {
        intervals_.push_back(current);
        ++offsets_[cell + 1];
        current = next;
      }
    }
    intervals_.push_back(current);
    ++offsets_[cell + 1];
  }
  for (std::size_t c = 1; c < offsets_.size(); ++c) offsets_[c] += offsets_[c - 1];
}

bool ReservationTable::taken(int x, int y, int t) const {
  if (intervals_.empty() || x < 0 || y < 0 || x >= width_ || y >= height_) return false;
  const std::int32_t cell = y * width_ + x;
  const auto begin = intervals_.begin() + offsets_[cell];
  const auto end = intervals_.begin() + offsets_[cell + 1];
  if (begin == end) return false;
  // The last interval starting at or before t.
  auto it = std::upper_bound(begin, end, t, [](int v, const Interval& in) { return v < in.first; });
  if (it == begin) return false;
  --it;
  return it->last == kForever || t <= it->last;
}

bool ReservationTable::taken(const CellSet& set, Cell origin, int t) const {
  if (intervals_.empty()) return false;
  for (const auto& run : set.runs()) {
    for (int x = run.x0; x <= run.x1; ++x) {
      if (taken(origin.x + x, origin.y + run.dy, t)) return true;
    }
  }
  return false;
}

void ReservationTable::takenIntervals(const CellSet& set, Cell origin, std::vector<std::pair<int, int>>& out) const {
  if (intervals_.empty()) return;
  for (const auto& run : set.runs()) {
    const int y = origin.y + run.dy;
    for (int x = origin.x + run.x0; x <= origin.x + run.x1; ++x) {
      if (x < 0 || y < 0 || x >= width_ || y >= height_) continue;
      const std::int32_t cell = y * width_ + x;
      for (std::int32_t i = offsets_[cell]; i < offsets_[cell + 1]; ++i) out.emplace_back(intervals_[i].first, intervals_[i].last);
    }
  }
}

int ReservationTable::lastTaken(const CellSet& set, Cell origin) const {
  int last = -1;
  if (intervals_.empty()) return last;
  for (const auto& run : set.runs()) {
    const int y = origin.y + run.dy;
    for (int x = origin.x + run.x0; x <= origin.x + run.x1; ++x) {
      if (x < 0 || y < 0 || x >= width_ || y >= height_) continue;
      const std::int32_t cell = y * width_ + x;
      if (offsets_[cell] == offsets_[cell + 1]) continue;
      last = std::max(last, intervals_[offsets_[cell + 1] - 1].last);
    }
  }
  return last;
}

}  // namespace fleet_planner
