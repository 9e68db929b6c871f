#include "fleet_planner/model/footprint_cells.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <mutex>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/model/geometry.h"

namespace fleet_planner {

namespace {

using geometry::Vec2;
using Polygon = std::vector<Vec2>;

// Every cell offset in the square of half-size `r` (cells) around the origin satisfying `covers`.
template <class Covers>
CellSet cellsWhere(double r, Covers covers) {
  const int n = static_cast<int>(std::ceil(r)) + 1;
  std::vector<Cell> cells;
  for (int dy = -n; dy <= n; ++dy) {
    for (int dx = -n; dx <= n; ++dx) {
      if (covers(Vec2(dx, dy))) cells.push_back({dx, dy});
    }
  }
  return CellSet::fromCells(std::move(cells));
}

Polygon rotated(const Polygon& polygon, int heading) {
  Polygon out;
  out.reserve(polygon.size());
  for (const Vec2& p : polygon) out.push_back(geometry::rotateQuarter(p, kQuarterTurns[heading]));
  return out;
}

// The star hull about the origin: one triangle from the origin to each edge (degenerate skipped).
std::vector<Polygon> starHull(const Polygon& polygon) {
  std::vector<Polygon> triangles;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % polygon.size()];
    if (std::abs(a.x() * b.y() - a.y() * b.x()) > geometry::kEps) {
      triangles.push_back({Vec2::Zero(), a, b});
    }
  }
  return triangles;
}

bool anyTriangleCovers(const std::vector<Polygon>& triangles, const Vec2& c, double half) {
  for (const auto& t : triangles) {
    if (geometry::squareOverlapsPolygon(c, t, half)) return true;
  }
  return false;
}

// Cells swept by the polygon `first` turning in place by `turn` radians (counter-clockwise when
// positive) to `last`. The sweep of a star-shaped set is both end poses plus, for every vertex,
// the sector its radius sweeps: the farthest point of any ray lies on an edge whose maximum is at
// a vertex. A cell counts when the sweep reaches more than `tolerance` into it (the cell shrunk
// by `tolerance` on every side); the caller adds both end poses exactly.
CellSet sectorSweep(const Polygon& first, const Polygon& last, double turn, double reach, double tolerance) {
  const double half = 0.5 - tolerance;
  const auto hull_first = starHull(first);
  const auto hull_last = starHull(last);
  struct Sector {
    double r, a0, a1;
  };
  std::vector<Sector> sectors;
  for (const Vec2& v : first) {
    const double r = v.norm();
    if (r < geometry::kEps) continue;
    const double a = std::atan2(v.y(), v.x());
    sectors.push_back(turn >= 0 ? Sector{r, a, a + turn} : Sector{r, a + turn, a});
  }
  return cellsWhere(reach, [&](const Vec2& c) {
    if (geometry::squareOverlapsPolygon(c, first, half)) return true;
    if (anyTriangleCovers(hull_first, c, half) || anyTriangleCovers(hull_last, c, half)) return true;
    for (const auto& s : sectors) {
      if (geometry::squareOverlapsSector(c, s.r, s.a0, s.a1, half)) return true;
    }
    return false;
  });
}

// Cells swept by the polygon (at `heading`) turning 90 degrees, counter-clockwise if ccw.
CellSet rotationSweep(const Polygon& outline, int heading, bool ccw, double reach, double tolerance) {
  const int end_heading = ccw ? kRotateCcw[heading] : kRotateCw[heading];
  return sectorSweep(rotated(outline, heading), rotated(outline, end_heading),
                     ccw ? geometry::kPi / 2 : -geometry::kPi / 2, reach, tolerance);
}

Polygon rotatedBy(const Polygon& polygon, double yaw) {
  const double c = std::cos(yaw), s = std::sin(yaw);
  Polygon out;
  out.reserve(polygon.size());
  for (const Vec2& p : polygon) out.push_back(Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y()));
  return out;
}

std::size_t hashCells(const CellSet& set, std::size_t seed) {
  for (const auto& r : set.runs()) {
    for (int v : {r.dy, r.x0, r.x1}) {
      seed ^= std::hash<int>()(v) + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2);
    }
  }
  return seed;
}

// The cells of a footprint at a yaw or turning between two yaws (`turn`), computed once:
// a robot at a yaw off the grid headings has its shapes asked for by the lattice connection, the
// plan's assembly and every validation of its plan, and each costs trigonometry over every cell
// near the footprint (about half a millisecond for a real robot at 0.05 m). Thread-safe; the
// last kKept distinct shapes are kept.
template <class Make>
CellSet remembered(const Footprint& footprint, bool turn, double from, double to, Make make) {
  struct Shape {
    Footprint footprint;
    bool turn;
    double from, to;
    CellSet cells;
  };
  constexpr std::size_t kKept = 1024;
  static std::mutex mutex;
  static std::deque<Shape> kept;  // newest first
  const auto find = [&]() -> const CellSet* {
    for (const Shape& k : kept) {
      if (k.turn == turn && k.from == from && k.to == to && k.footprint == footprint) return &k.cells;
    }
    return nullptr;
  };
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (const CellSet* cells = find()) return *cells;
  }
  CellSet made = make();  // outside the lock: other threads' lookups need not wait
  const std::lock_guard<std::mutex> lock(mutex);
  if (find() == nullptr) {
    kept.push_front({footprint, turn, from, to, made});
    if (kept.size() > kKept) kept.pop_back();
  }
  return made;
}

}  // namespace

FootprintCells::FootprintCells(const Footprint& footprint, int step) : footprint_(footprint), step_(step) {
  const std::string problem = footprintProblem(footprint);
  if (!problem.empty()) throw InvalidInput("invalid footprint (" + footprint.describe() + "): " + problem);
  if (step < 1) throw InvalidInput("lattice step must be >= 1 cell (got " + std::to_string(step) + ")");

  const double reach = footprint.circumscribedRadius();
  const Polygon outline = footprint.outline();
  for (int h = 0; h < kHeadings; ++h) {
    if (footprint.kind == Footprint::Kind::Circle) {
      body_[h] = cellsWhere(reach, [&](const Vec2& c) { return geometry::squareOverlapsDisc(c, reach); });
    } else {
      const Polygon poly = rotated(outline, h);
      body_[h] = cellsWhere(reach, [&](const Vec2& c) { return geometry::squareOverlapsPolygon(c, poly); });
    }
  }
  for (int h = 0; h < kHeadings; ++h) {
    auto& sw = swept_[h];
    sw[static_cast<int>(Action::Wait)] = body_[h];
    for (int dir = 0; dir < 2; ++dir) {  // forward, backward
      const int sign = dir == 0 ? 1 : -1;
      CellSet cells = body_[h];
      for (int k = 1; k <= step; ++k) {
        cells = cells.unionWith(body_[h], {sign * k * kHeadingStep[h].x, sign * k * kHeadingStep[h].y});
        moves_[h][dir].push_back(cells);
      }
    }
    sw[static_cast<int>(Action::Forward)] = moves_[h][0].back();
    sw[static_cast<int>(Action::Backward)] = moves_[h][1].back();
    for (bool ccw : {true, false}) {
      const Action a = ccw ? Action::RotateCcw : Action::RotateCw;
      const int end = ccw ? kRotateCcw[h] : kRotateCw[h];
      CellSet cells = footprint.kind == Footprint::Kind::Circle
                          ? body_[h]
                          : rotationSweep(outline, h, ccw, reach, footprint.sweep_tolerance);
      // Both end poses are part of every rotation, whatever rounding did above.
      sw[static_cast<int>(a)] = cells.unionWith(body_[h], {0, 0}).unionWith(body_[end], {0, 0});
    }
  }
  hash_ = 0;
  for (int h = 0; h < kHeadings; ++h) {
    for (int a = 0; a < kActions; ++a) {
      max_norm_sq_ = std::max(max_norm_sq_, swept_[h][a].maxNormSq());
      hash_ = hashCells(swept_[h][a], hash_);
    }
    hash_ = hashCells(body_[h], hash_);
  }
}

CellSet footprintCellsAt(const Footprint& footprint, double yaw) {
  return remembered(footprint, false, yaw, yaw, [&] { return footprintCellsAt(footprint, yaw, Vec2(0, 0)); });
}

CellSet footprintCellsAt(const Footprint& footprint, double yaw, const Vec2& offset) {
  // A cell (dx, dy) is the unit square centred there; relative to the robot's origin its centre
  // is (dx, dy) - offset.
  const double reach = footprint.circumscribedRadius() + offset.cwiseAbs().maxCoeff();
  if (footprint.kind == Footprint::Kind::Circle) {
    const double r = footprint.circumscribedRadius();
    return cellsWhere(reach, [&](const Vec2& c) { return geometry::squareOverlapsDisc(c - offset, r); });
  }
  // A grid heading's yaw gives exactly the grid heading's cells (no rounding at cell borders).
  const double quarters = yaw / (geometry::kPi / 2);
  const bool on_grid = std::abs(quarters - std::round(quarters)) < 1e-9;
  const Polygon poly = on_grid ? Polygon{} : rotatedBy(footprint.outline(), yaw);
  Polygon quarter;
  if (on_grid) {
    const int q = ((static_cast<int>(std::lround(quarters)) % 4) + 4) % 4;
    for (const Vec2& p : footprint.outline()) quarter.push_back(geometry::rotateQuarter(p, q));
  }
  const Polygon& shape = on_grid ? quarter : poly;
  return cellsWhere(reach, [&](const Vec2& c) { return geometry::squareOverlapsPolygon(c - offset, shape); });
}

CellSet turnSweep(const Footprint& footprint, double from_yaw, double to_yaw) {
  if (footprint.kind == Footprint::Kind::Circle) return footprintCellsAt(footprint, from_yaw);
  return remembered(footprint, true, from_yaw, to_yaw, [&] {
    const CellSet start = footprintCellsAt(footprint, from_yaw), end = footprintCellsAt(footprint, to_yaw);
    const double turn = std::remainder(to_yaw - from_yaw, 2 * geometry::kPi);  // in [-pi, pi]
    const CellSet swept = sectorSweep(rotatedBy(footprint.outline(), from_yaw),
                                      rotatedBy(footprint.outline(), from_yaw + turn), turn,
                                      footprint.circumscribedRadius(), footprint.sweep_tolerance);
    return swept.unionWith(start, {0, 0}).unionWith(end, {0, 0});
  });
}

bool FootprintCells::sameCells(const FootprintCells& other) const {
  if (hash_ != other.hash_ || step_ != other.step_) return false;
  for (int h = 0; h < kHeadings; ++h) {
    if (body_[h] != other.body_[h]) return false;
    for (int a = 0; a < kActions; ++a) {
      if (swept_[h][a] != other.swept_[h][a]) return false;
    }
  }
  return true;
}

std::shared_ptr<const FootprintCells> sharedFootprintCells(const Footprint& footprint, int step) {
  constexpr std::size_t kKept = 64;
  static std::mutex mutex;
  static std::deque<std::shared_ptr<const FootprintCells>> kept;  // newest first
  const auto find = [&]() -> std::shared_ptr<const FootprintCells> {
    for (const auto& cells : kept) {
      if (cells->step() == step && cells->footprint() == footprint) return cells;
    }
    return nullptr;
  };
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (auto cells = find()) return cells;
  }
  // Built outside the lock: other threads' lookups need not wait for the geometry.
  auto made = std::make_shared<const FootprintCells>(footprint, step);
  const std::lock_guard<std::mutex> lock(mutex);
  if (auto cells = find()) return cells;  // another thread built it meanwhile
  kept.push_front(made);
  if (kept.size() > kKept) kept.pop_back();
  return made;
}

}  // namespace fleet_planner
