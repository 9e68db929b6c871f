#include "fleet_planner/solvers/search/reservation_table.h"

#include <algorithm>
#include <unordered_map>

#include "fleet_planner/model/action.h"
#include "fleet_planner/model/contact_probe.h"
#include "fleet_planner/model/robot_cells.h"
#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

ReservationTable::ReservationTable(int width, int height, const std::vector<MovingObstacle>& moving,
                                   const FleetGraphs& graphs, const ActionModel& model)
    : width_(width), height_(height) {
  blocks_x_ = (width + kBlock - 1) / kBlock;
  blocks_y_ = (height + kBlock - 1) / kBlock;
  std::vector<Entry> entries;
  // The probe pitch each reserved set allows; the footprints' own sets are looked at once.
  std::unordered_map<const CellSet*, int> pitch_of;
  auto allowPitch = [&](const CellSet& set, bool shared) {
    if (pitch_ == 1) return;
    const auto it = shared ? pitch_of.find(&set) : pitch_of.end();
    const int pitch = it != pitch_of.end() ? it->second : (fourConnected(set) ? largestSquare(set) : 1);
    if (shared) pitch_of.emplace(&set, pitch);
    pitch_ = std::max(1, std::min(pitch_, pitch));
  };
  // A robot covers most cells of its sweep for several steps in a row: each cell's interval is
  // extended while the robot's reservations of it overlap or touch, and becomes an entry when a
  // later one does not (or the robot's path ends). The lists built from the entries merge the
  // same way, so they are the same; there are several times fewer entries to bucket and sort.
  std::vector<Interval> open(static_cast<std::size_t>(width_) * height_, Interval{-1, -1});
  std::vector<std::int32_t> open_cells;
  auto touches = [](const Interval& a, const Interval& b) {  // overlap or adjacent, no overflow
    return (a.last == kForever || b.first <= a.last + 1) && (b.last == kForever || a.first <= b.last + 1);
  };
  auto reserve = [&](const CellSet& set, const GridPose& at, int first, int last, bool shared) {
    allowPitch(set, shared);
    const Interval in{first, last};
    for (const auto& run : set.runs()) {
      const int y = at.y + run.dy;
      for (int x = at.x + run.x0; x <= at.x + run.x1; ++x) {
        if (x < 0 || y < 0 || x >= width_ || y >= height_) continue;
        const std::int32_t cell = y * width_ + x;
        Interval& o = open[cell];
        if (o.first < 0) {
          o = in;
          open_cells.push_back(cell);
        } else if (touches(o, in)) {
          o = {std::min(o.first, in.first), std::max(o.last, in.last)};
        } else {
          entries.push_back({cell, o});
          o = in;
        }
      }
    }
  };
  auto flush = [&] {
    for (std::int32_t cell : open_cells) {
      entries.push_back({cell, open[cell]});
      open[cell] = {-1, -1};
    }
    open_cells.clear();
  };
  for (const MovingObstacle& m : moving) {
    if (m.path.empty()) throw InvalidInput("moving obstacle of robot index " + std::to_string(m.robot) + " has an empty path");
    const FootprintCells& cells = graphs.cells(m.robot);
    Robot shape;  // only its yaws: turns onto the path and off it (robot_cells.h)
    shape.start_yaw = m.start_yaw;
    shape.start_turn = m.start_turn;
    shape.target_yaw = m.target_yaw;
    const RobotCells robot_cells(shape, cells, m.path);
    if (!robot_cells.shapeProblem().empty()) {
      throw InvalidInput("moving obstacle of robot index " + std::to_string(m.robot) + ": " + robot_cells.shapeProblem());
    }
    const int end = static_cast<int>(m.path.size()) - 1;
    for (int t = 0; t < end; ++t) {
      const bool held = t <= m.held_through;
      auto take = [&](const CellSet& set, int last, bool shared) {
        reserve(set, m.path[t], held ? 0 : t, held && m.held_for_good ? kForever : last, shared);
      };
      if ((t <= m.start_turn && m.start_yaw) || (t == end - 1 && m.target_yaw)) {
        take(*robot_cells.sweepAt(t, model), t, false);  // a rest at or a turn from or to a yaw
        continue;
      }
      const auto action = actionBetween(m.path[t], m.path[t + 1], model);
      if (!action) {
        throw InvalidInput("moving obstacle of robot index " + std::to_string(m.robot) + " makes an illegal step at t=" +
                           std::to_string(t));
      }
      // A run of waits is one reservation: merged plans wait for thousands of steps, and one
      // entry per cell and step made building the table most of the refinement's time.
      int last = t;
      if (*action == Action::Wait) {
        const int last_wait = m.target_yaw ? end - 2 : end - 1;  // the turn to the target yaw is no wait
        while (last + 1 <= last_wait && m.path[last + 2] == m.path[t]) ++last;
      }
      take(cells.swept(m.path[t].heading, *action), last, true);
      t = last;
    }
    reserve(robot_cells.bodyAt(end), m.path.back(), end <= m.held_through ? 0 : end, kForever, false);
    flush();
    last_change_ = std::max(last_change_, end);
  }
  std::vector<Entry> block_entries;
  block_entries.reserve(entries.size());
  for (const Entry& e : entries) {
    const int x = e.key % width_, y = e.key / width_;
    block_entries.push_back({(y / kBlock) * blocks_x_ + x / kBlock, e.interval});
  }
  buildLists(entries, static_cast<std::size_t>(width_) * height_, offsets_, intervals_);
  buildLists(block_entries, static_cast<std::size_t>(blocks_x_) * blocks_y_, block_offsets_, block_intervals_);
}

void ReservationTable::buildLists(std::vector<Entry>& entries, std::size_t keys, std::vector<std::int32_t>& offsets,
                                  std::vector<Interval>& intervals) {
  // Bucket the entries by key (counting sort: a global sort of a million entries was most of the
  // table's cost), then order each key's few intervals by their first step and merge them.
  std::vector<std::int32_t> start(keys + 1, 0);
  for (const Entry& e : entries) ++start[e.key + 1];
  for (std::size_t k = 1; k <= keys; ++k) start[k] += start[k - 1];
  std::vector<Interval> bucketed(entries.size());
  {
    std::vector<std::int32_t> next(start.begin(), start.end() - 1);
    for (const Entry& e : entries) bucketed[next[e.key]++] = e.interval;
  }
  offsets.assign(keys + 1, 0);
  intervals.clear();
  for (std::size_t key = 0; key < keys; ++key) {
    Interval* begin = bucketed.data() + start[key];
    Interval* end = bucketed.data() + start[key + 1];
    if (begin == end) continue;
    std::sort(begin, end, [](const Interval& a, const Interval& b) { return a.first < b.first; });
    Interval current = *begin;
    for (const Interval* next = begin + 1; next != end; ++next) {
      if (current.last == kForever) break;  // already held forever
      if (next->first <= current.last + 1) {
        current.last = next->last == kForever ? kForever : std::max(current.last, next->last);
      } else {
        intervals.push_back(current);
        ++offsets[key + 1];
        current = *next;
      }
    }
    intervals.push_back(current);
    ++offsets[key + 1];
  }
  for (std::size_t k = 1; k < offsets.size(); ++k) offsets[k] += offsets[k - 1];
}

bool ReservationTable::contains(const Interval* begin, const Interval* end, int t) {
  if (begin == end) return false;
  // The last interval starting at or before t.
  const Interval* it = std::upper_bound(begin, end, t, [](int v, const Interval& in) { return v < in.first; });
  if (it == begin) return false;
  --it;
  return it->last == kForever || t <= it->last;
}

bool ReservationTable::taken(int x, int y, int t) const {
  if (intervals_.empty() || x < 0 || y < 0 || x >= width_ || y >= height_) return false;
  const std::int32_t cell = y * width_ + x;
  return contains(intervals_.data() + offsets_[cell], intervals_.data() + offsets_[cell + 1], t);
}

bool ReservationTable::taken(const CellSet& set, Cell origin, int t) const {
  if (intervals_.empty() || set.empty()) return false;
  // The blocks under the set's bounding box, clipped to the map: if none is taken at t, no cell is.
  const int x0 = std::max(0, origin.x + set.minX()), x1 = std::min(width_ - 1, origin.x + set.maxX());
  const int y0 = std::max(0, origin.y + set.minY()), y1 = std::min(height_ - 1, origin.y + set.maxY());
  if (x0 > x1 || y0 > y1) return false;
  for (int by = y0 / kBlock; by <= y1 / kBlock; ++by) {
    for (int bx = x0 / kBlock; bx <= x1 / kBlock; ++bx) {
      const std::int32_t b = by * blocks_x_ + bx;
      if (contains(block_intervals_.data() + block_offsets_[b], block_intervals_.data() + block_offsets_[b + 1], t)) {
        return cellsTaken(set, origin, t);
      }
    }
  }
  return false;
}

bool ReservationTable::cellsTaken(const CellSet& set, Cell origin, int t) const {
  for (const auto& run : set.runs()) {
    const int y = origin.y + run.dy;
    if (y < 0 || y >= height_) continue;
    const int x0 = std::max(0, origin.x + run.x0), x1 = std::min(width_ - 1, origin.x + run.x1);
    const std::int32_t* offset = offsets_.data() + static_cast<std::size_t>(y) * width_;
    for (int x = x0; x <= x1; ++x) {
      if (offset[x] != offset[x + 1] && contains(intervals_.data() + offset[x], intervals_.data() + offset[x + 1], t)) {
        return true;
      }
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
