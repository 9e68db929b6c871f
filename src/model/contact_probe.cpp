#include "fleet_planner/model/contact_probe.h"

#include <algorithm>
#include <vector>

namespace fleet_planner {

namespace {

// Non-negative remainder.
int mod(int v, int m) { return ((v % m) + m) % m; }

}  // namespace

CellSet contactProbe(const CellSet& set, int side) {
  if (side <= 1) return set;
  std::vector<Cell> kept;
  for (const CellSet::Run& r : set.runs()) {
    for (int x = r.x0; x <= r.x1; ++x) {
      const bool border = x == r.x0 || x == r.x1 || !set.contains(x, r.dy - 1) || !set.contains(x, r.dy + 1);
      if (border || (mod(x, side) == 0 && mod(r.dy, side) == 0)) kept.push_back({x, r.dy});
    }
  }
  return CellSet::fromCells(std::move(kept));
}

int largestSquare(const CellSet& set) {
  if (set.empty()) return 0;
  // Dynamic programme over the bounding box, row by row: cur[i] is the side of the largest
  // square of the set whose corner of largest x and y is (minX + i - 1, y).
  const int w = set.maxX() - set.minX() + 1;
  std::vector<int> prev(w + 1, 0), cur(w + 1, 0);
  int best = 0;
  for (int y = set.minY(); y <= set.maxY(); ++y) {
    for (int i = 1; i <= w; ++i) {
      const int x = set.minX() + i - 1;
      cur[i] = set.contains(x, y) ? 1 + std::min({prev[i], prev[i - 1], cur[i - 1]}) : 0;
      best = std::max(best, cur[i]);
    }
    std::swap(prev, cur);
  }
  return best;
}

bool fourConnected(const CellSet& set) {
  const std::vector<Cell> cells = set.cells();
  if (cells.empty()) return true;
  const int w = set.maxX() - set.minX() + 1, h = set.maxY() - set.minY() + 1;
  std::vector<char> member(static_cast<std::size_t>(w) * h, 0), seen(member.size(), 0);
  auto at = [&](int x, int y) { return static_cast<std::size_t>(y - set.minY()) * w + (x - set.minX()); };
  for (const Cell& c : cells) member[at(c.x, c.y)] = 1;
  std::vector<Cell> stack{cells.front()};
  seen[at(cells.front().x, cells.front().y)] = 1;
  std::size_t reached = 0;
  while (!stack.empty()) {
    const Cell c = stack.back();
    stack.pop_back();
    ++reached;
    const Cell next[4] = {{c.x + 1, c.y}, {c.x - 1, c.y}, {c.x, c.y + 1}, {c.x, c.y - 1}};
    for (const Cell& n : next) {
      if (n.x < set.minX() || n.x > set.maxX() || n.y < set.minY() || n.y > set.maxY()) continue;
      const std::size_t i = at(n.x, n.y);
      if (member[i] && !seen[i]) {
        seen[i] = 1;
        stack.push_back(n);
      }
    }
  }
  return reached == cells.size();
}

}  // namespace fleet_planner
