#include "fleet_planner/model/cell_set.h"

#include <algorithm>

namespace fleet_planner {

CellSet CellSet::fromCells(std::vector<Cell> cells) {
  std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) {
    return a.y != b.y ? a.y < b.y : a.x < b.x;
  });
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  CellSet set;
  if (cells.empty()) return set;
  set.size_ = cells.size();
  set.min_x_ = set.max_x_ = cells.front().x;
  set.min_y_ = cells.front().y;
  set.max_y_ = cells.back().y;
  for (const Cell& c : cells) {
    set.min_x_ = std::min(set.min_x_, c.x);
    set.max_x_ = std::max(set.max_x_, c.x);
    set.max_norm_sq_ = std::max(set.max_norm_sq_, c.x * c.x + c.y * c.y);
    if (!set.runs_.empty() && set.runs_.back().dy == c.y && set.runs_.back().x1 + 1 == c.x) {
      set.runs_.back().x1 = c.x;
    } else {
      set.runs_.push_back({c.y, c.x, c.x});
    }
  }
  return set;
}

bool CellSet::contains(int dx, int dy) const {
  for (const Run& r : runs_) {
    if (r.dy == dy && r.x0 <= dx && dx <= r.x1) return true;
  }
  return false;
}

std::vector<Cell> CellSet::cells() const {
  std::vector<Cell> out;
  out.reserve(size_);
  for (const Run& r : runs_) {
    for (int x = r.x0; x <= r.x1; ++x) out.push_back({x, r.dy});
  }
  return out;
}

CellSet CellSet::unionWith(const CellSet& other, Cell shift) const {
  std::vector<Cell> all = cells();
  for (const Cell& c : other.cells()) all.push_back({c.x + shift.x, c.y + shift.y});
  return fromCells(std::move(all));
}

bool CellSet::commonCell(const CellSet& a, Cell pa, const CellSet& b, Cell pb, Cell& cell) {
  if (a.runs_.empty() || b.runs_.empty()) return false;
  if (a.max_x_ + pa.x < b.min_x_ + pb.x || b.max_x_ + pb.x < a.min_x_ + pa.x ||
      a.max_y_ + pa.y < b.min_y_ + pb.y || b.max_y_ + pb.y < a.min_y_ + pa.y) {
    return false;
  }
  // Merge the runs of both sets in (row, column) order.
  std::size_t i = 0, j = 0;
  while (i < a.runs_.size() && j < b.runs_.size()) {
    const Run& ra = a.runs_[i];
    const Run& rb = b.runs_[j];
    const int ya = ra.dy + pa.y, yb = rb.dy + pb.y;
    if (ya < yb) {
      ++i;
    } else if (yb < ya) {
      ++j;
    } else {
      const int a0 = ra.x0 + pa.x, a1 = ra.x1 + pa.x;
      const int b0 = rb.x0 + pb.x, b1 = rb.x1 + pb.x;
      if (std::max(a0, b0) <= std::min(a1, b1)) {
        cell = {std::max(a0, b0), ya};
        return true;
      }
      if (a1 < b1) {
        ++i;
      } else {
        ++j;
      }
    }
  }
  return false;
}

}  // namespace fleet_planner
