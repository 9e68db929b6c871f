#include "fleet_planner/model/geometry.h"

#include <algorithm>
#include <cmath>

namespace fleet_planner::geometry {

namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

bool strictlyInsideSquare(const Vec2& p, const Vec2& c, double half) {
  return std::abs(p.x() - c.x()) < half - kEps && std::abs(p.y() - c.y()) < half - kEps;
}

// Orientation of c relative to the line a->b: +1 left, -1 right, 0 collinear (within kEps).
int orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double v = cross(b - a, c - a);
  return v > kEps ? 1 : (v < -kEps ? -1 : 0);
}

bool onSegment(const Vec2& a, const Vec2& b, const Vec2& p) {
  return p.x() <= std::max(a.x(), b.x()) + kEps && p.x() >= std::min(a.x(), b.x()) - kEps &&
         p.y() <= std::max(a.y(), b.y()) + kEps && p.y() >= std::min(a.y(), b.y()) - kEps;
}

bool segmentsTouch(const Vec2& p1, const Vec2& p2, const Vec2& q1, const Vec2& q2) {
  const int o1 = orientation(p1, p2, q1), o2 = orientation(p1, p2, q2);
  const int o3 = orientation(q1, q2, p1), o4 = orientation(q1, q2, p2);
  if (o1 != o2 && o3 != o4 && o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0) return true;
  return (o1 == 0 && onSegment(p1, p2, q1)) || (o2 == 0 && onSegment(p1, p2, q2)) ||
         (o3 == 0 && onSegment(q1, q2, p1)) || (o4 == 0 && onSegment(q1, q2, p2));
}

// The arc of radius r over angles [a0, a1] passes through the open square of half-size `half`
// centred at c.
bool arcEntersSquare(const Vec2& c, double half, double r, double a0, double a1) {
  // Between two consecutive crossings of the square's edge lines the arc is either inside or
  // outside the square, so testing the midpoint of every piece is exact.
  std::vector<double> cuts{a0, a1};
  auto add = [&](double phi) {
    const double two_pi = 2.0 * kPi;
    double t = std::fmod(phi - a0, two_pi);
    if (t < 0) t += two_pi;
    if (t > 0 && a0 + t < a1) cuts.push_back(a0 + t);
  };
  for (double lx : {c.x() - half, c.x() + half}) {
    if (std::abs(lx) <= r) {
      const double phi = std::acos(lx / r);
      add(phi);
      add(-phi);
    }
  }
  for (double ly : {c.y() - half, c.y() + half}) {
    if (std::abs(ly) <= r) {
      const double phi = std::asin(ly / r);
      add(phi);
      add(kPi - phi);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double mid = 0.5 * (cuts[i] + cuts[i + 1]);
    if (strictlyInsideSquare(Vec2(r * std::cos(mid), r * std::sin(mid)), c, half)) return true;
  }
  return false;
}

}  // namespace

double signedArea(const std::vector<Vec2>& polygon) {
  double area = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    area += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  }
  return 0.5 * area;
}

bool selfIntersecting(const std::vector<Vec2>& polygon) {
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    if ((polygon[i] - polygon[(i + 1) % n]).norm() < kEps) return true;
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool neighbours = j == i + 1 || (i == 0 && j == n - 1);
      const Vec2 &p1 = polygon[i], &p2 = polygon[(i + 1) % n];
      const Vec2 &q1 = polygon[j], &q2 = polygon[(j + 1) % n];
      if (neighbours) {
        // Neighbours share one vertex; they must not fold back onto each other.
        const Vec2& shared = (j == i + 1) ? p2 : p1;
        const Vec2& p_other = (j == i + 1) ? p1 : p2;
        const Vec2& q_other = (j == i + 1) ? q2 : q1;
        if (orientation(p_other, shared, q_other) == 0 &&
            (p_other - shared).dot(q_other - shared) > 0)
          return true;
        continue;
      }
      if (segmentsTouch(p1, p2, q1, q2)) return true;
    }
  }
  return false;
}

Vec2 rotateQuarter(const Vec2& p, int quarter_turns) {
  switch (((quarter_turns % 4) + 4) % 4) {
    case 1:
      return {-p.y(), p.x()};
    case 2:
      return {-p.x(), -p.y()};
    case 3:
      return {p.y(), -p.x()};
    default:
      return p;
  }
}

bool pointInPolygon(const Vec2& p, const std::vector<Vec2>& polygon) {
  bool inside = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 &a = polygon[i], &b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

bool segmentEntersSquare(const Vec2& a, const Vec2& b, const Vec2& c, double half) {
  // Liang-Barsky clip against the closed square; the clipped piece reaches the open interior
  // exactly when its midpoint lies in the interior.
  double t0 = 0.0, t1 = 1.0;
  const Vec2 d = b - a;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a.x() - (c.x() - half), (c.x() + half) - a.x(), a.y() - (c.y() - half),
                       (c.y() + half) - a.y()};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0.0) {
      if (q[k] < 0.0) return false;
      continue;
    }
    const double t = q[k] / p[k];
    if (p[k] < 0.0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
    if (t0 > t1) return false;
  }
  return strictlyInsideSquare(a + 0.5 * (t0 + t1) * d, c, half);
}

bool squareOverlapsPolygon(const Vec2& c, const std::vector<Vec2>& polygon, double half) {
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (segmentEntersSquare(polygon[i], polygon[(i + 1) % n], c, half)) return true;
  }
  // No edge crosses the open square: it is wholly inside or wholly outside the polygon.
  return pointInPolygon(c, polygon);
}

bool squareOverlapsDisc(const Vec2& c, double r) {
  const double dx = std::max(std::abs(c.x()) - 0.5, 0.0);
  const double dy = std::max(std::abs(c.y()) - 0.5, 0.0);
  const double reach = r - kEps;
  return reach > 0 && dx * dx + dy * dy < reach * reach;
}

bool squareOverlapsSector(const Vec2& c, double r, double a0, double a1, double half) {
  const Vec2 e0(std::cos(a0), std::sin(a0)), e1(std::cos(a1), std::sin(a1));
  // Sector and square are convex: their interiors meet iff the sector's boundary enters the
  // open square, or the square lies inside the sector (then so does its centre).
  if (segmentEntersSquare(Vec2::Zero(), r * e0, c, half)) return true;
  if (segmentEntersSquare(Vec2::Zero(), r * e1, c, half)) return true;
  if (arcEntersSquare(c, half, r, a0, a1)) return true;
  return c.norm() < r - kEps && cross(e0, c) > kEps && cross(c, e1) > kEps;
}

}  // namespace fleet_planner::geometry
