#include "fleet_planner/model/obstacle_index.h"

#include <algorithm>
#include <limits>

namespace fleet_planner {

namespace {

constexpr std::int64_t kFar = std::numeric_limits<std::int64_t>::max() / 4;

// One-dimensional squared distance transform of f (lower envelope of parabolas), in place.
void transform1d(std::vector<std::int64_t>& f, std::vector<int>& v, std::vector<double>& z,
                 std::vector<std::int64_t>& out) {
  const int n = static_cast<int>(f.size());
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (f[q] >= kFar) continue;
    while (k >= 0) {
      const int p = v[k];
      const double s = (static_cast<double>(f[q] + 1LL * q * q) - static_cast<double>(f[p] + 1LL * p * p)) /
                       (2.0 * (q - p));
      if (s <= z[k]) {
        --k;
      } else {
        break;
      }
    }
    ++k;
    v[k] = q;
    z[k] = k == 0 ? -1e300 : (static_cast<double>(f[q] + 1LL * q * q) -
                              static_cast<double>(f[v[k - 1]] + 1LL * v[k - 1] * v[k - 1])) /
                                 (2.0 * (q - v[k - 1]));
  }
  if (k < 0) {
    std::fill(out.begin(), out.end(), kFar);
    return;
  }
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (j < k && z[j + 1] < q) ++j;
    const std::int64_t d = q - v[j];
    out[q] = d * d + f[v[j]];
  }
}

}  // namespace

std::vector<std::int64_t> squaredDistanceToBlocked(const GridMap& map) {
  // Pad by one blocked cell on every side so the map's border counts as an obstacle.
  const int w = map.width() + 2, h = map.height() + 2;
  std::vector<std::int64_t> grid(static_cast<std::size_t>(w) * h, kFar);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (map.blocked(x - 1, y - 1)) grid[static_cast<std::size_t>(y) * w + x] = 0;
    }
  }
  const int longest = std::max(w, h);
  std::vector<std::int64_t> f(longest), out(longest);
  std::vector<int> v(longest);
  std::vector<double> z(longest + 1);
  // Columns, then rows.
  f.resize(h);
  out.resize(h);
  for (int x = 0; x < w; ++x) {
    for (int y = 0; y < h; ++y) f[y] = grid[static_cast<std::size_t>(y) * w + x];
    transform1d(f, v, z, out);
    for (int y = 0; y < h; ++y) grid[static_cast<std::size_t>(y) * w + x] = out[y];
  }
  f.resize(w);
  out.resize(w);
  for (int y = 0; y < h; ++y) {
    std::copy_n(grid.begin() + static_cast<std::ptrdiff_t>(y) * w, w, f.begin());
    transform1d(f, v, z, out);
    std::copy_n(out.begin(), w, grid.begin() + static_cast<std::ptrdiff_t>(y) * w);
  }
  std::vector<std::int64_t> result(static_cast<std::size_t>(map.width()) * map.height());
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      result[static_cast<std::size_t>(y) * map.width() + x] =
          grid[static_cast<std::size_t>(y + 1) * w + (x + 1)];
    }
  }
  return result;
}

std::vector<std::int64_t> squaredChessboardToBlocked(const GridMap& map) {
  // Two passes over the padded grid, each taking the 8-neighbours already visited + 1: the
  // exact chessboard distance.
  const int w = map.width() + 2, h = map.height() + 2;
  constexpr std::int32_t kNone = std::numeric_limits<std::int32_t>::max() / 2;
  std::vector<std::int32_t> d(static_cast<std::size_t>(w) * h, kNone);
  auto at = [&](int x, int y) -> std::int32_t& { return d[static_cast<std::size_t>(y) * w + x]; };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (x == 0 || y == 0 || x == w - 1 || y == h - 1 || map.blocked(x - 1, y - 1)) at(x, y) = 0;
    }
  }
  for (int y = 1; y < h - 1; ++y) {
    for (int x = 1; x < w - 1; ++x) {
      at(x, y) = std::min({at(x, y), at(x - 1, y) + 1, at(x - 1, y - 1) + 1, at(x, y - 1) + 1, at(x + 1, y - 1) + 1});
    }
  }
  for (int y = h - 2; y >= 1; --y) {
    for (int x = w - 2; x >= 1; --x) {
      at(x, y) = std::min({at(x, y), at(x + 1, y) + 1, at(x + 1, y + 1) + 1, at(x, y + 1) + 1, at(x - 1, y + 1) + 1});
    }
  }
  std::vector<std::int64_t> result(static_cast<std::size_t>(map.width()) * map.height());
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      const std::int64_t c = at(x + 1, y + 1);
      result[static_cast<std::size_t>(y) * map.width() + x] = c * c;
    }
  }
  return result;
}

ObstacleIndex::ObstacleIndex(const GridMap& map, Clearance clearance)
    : width_(map.width()),
      height_(map.height()),
      clearance_sq_(clearance == Clearance::Euclidean ? squaredDistanceToBlocked(map) : squaredChessboardToBlocked(map)) {
  row_prefix_.assign(static_cast<std::size_t>(width_ + 1) * height_, 0);
  for (int y = 0; y < height_; ++y) {
    std::int32_t* row = &row_prefix_[static_cast<std::size_t>(y) * (width_ + 1)];
    for (int x = 0; x < width_; ++x) row[x + 1] = row[x] + (map.blocked(x, y) ? 1 : 0);
  }
}

bool ObstacleIndex::blocked(const CellSet& set, Cell origin) const {
  if (set.empty()) return false;
  if (origin.x + set.minX() < 0 || origin.y + set.minY() < 0 ||
      origin.x + set.maxX() >= width_ || origin.y + set.maxY() >= height_) {
    return true;
  }
  if (set.maxNormSq() < clearanceSq(origin.x, origin.y)) return false;
  for (const auto& run : set.runs()) {
    const std::int32_t* row = &row_prefix_[static_cast<std::size_t>(origin.y + run.dy) * (width_ + 1)];
    if (row[origin.x + run.x1 + 1] != row[origin.x + run.x0]) return true;
  }
  return false;
}

}  // namespace fleet_planner
