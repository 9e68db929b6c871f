#include "fleet_planner/model/footprint.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "fleet_planner/model/geometry.h"

namespace fleet_planner {

Footprint Footprint::circle(double radius) {
  Footprint f;
  f.kind = Kind::Circle;
  f.radius = radius;
  return f;
}

Footprint Footprint::block(double min_x, double min_y, double max_x, double max_y) {
  Footprint f;
  f.kind = Kind::Block;
  f.min_x = min_x;
  f.min_y = min_y;
  f.max_x = max_x;
  f.max_y = max_y;
  return f;
}

Footprint Footprint::polygon(std::vector<Eigen::Vector2d> points) {
  Footprint f;
  f.kind = Kind::Polygon;
  f.points = std::move(points);
  return f;
}

std::vector<Eigen::Vector2d> Footprint::outline() const {
  switch (kind) {
    case Kind::Circle:
      return {};
    case Kind::Block:
      return {{min_x, min_y}, {max_x, min_y}, {max_x, max_y}, {min_x, max_y}};
    case Kind::Polygon:
      return points;
  }
  return {};
}

double Footprint::circumscribedRadius() const {
  if (kind == Kind::Circle) return radius;
  double r = 0.0;
  for (const auto& p : outline()) r = std::max(r, p.norm());
  return r;
}

std::string Footprint::describe() const {
  std::ostringstream out;
  switch (kind) {
    case Kind::Circle:
      out << "circle r=" << radius;
      break;
    case Kind::Block:
      out << "block [" << min_x << "," << max_x << "]x[" << min_y << "," << max_y << "]";
      break;
    case Kind::Polygon:
      out << "polygon of " << points.size() << " points";
      break;
  }
  if (sweep_tolerance != 0.0) out << " (sweep tolerance " << sweep_tolerance << ")";
  return out.str();
}

bool operator==(const Footprint& a, const Footprint& b) {
  if (a.kind != b.kind || a.sweep_tolerance != b.sweep_tolerance) return false;
  switch (a.kind) {
    case Footprint::Kind::Circle:
      return a.radius == b.radius;
    case Footprint::Kind::Block:
      return a.min_x == b.min_x && a.max_x == b.max_x && a.min_y == b.min_y && a.max_y == b.max_y;
    case Footprint::Kind::Polygon:
      return a.points == b.points;
  }
  return false;
}

std::string footprintProblem(const Footprint& f) {
  auto finite = [](double v) { return std::isfinite(v); };
  if (!(f.sweep_tolerance >= 0.0 && f.sweep_tolerance <= Footprint::kMaxSweepTolerance))
    return "sweep tolerance must be in [0, 0.25] cells";
  switch (f.kind) {
    case Footprint::Kind::Circle:
      if (!finite(f.radius)) return "circle radius is not a finite number";
      if (f.radius <= 0.0) return "circle radius must be positive";
      return "";
    case Footprint::Kind::Block:
      if (!finite(f.min_x) || !finite(f.max_x) || !finite(f.min_y) || !finite(f.max_y))
        return "block extents are not finite numbers";
      if (!(f.min_x < f.max_x) || !(f.min_y < f.max_y))
        return "block must have min_x < max_x and min_y < max_y";
      return "";
    case Footprint::Kind::Polygon: {
      if (f.points.size() < 3) return "polygon needs at least 3 points";
      for (const auto& p : f.points)
        if (!finite(p.x()) || !finite(p.y())) return "polygon point is not a finite number";
      if (std::abs(geometry::signedArea(f.points)) < 1e-9) return "polygon has zero area";
      if (geometry::selfIntersecting(f.points)) return "polygon edges intersect each other";
      return "";
    }
  }
  return "unknown footprint kind";
}

}  // namespace fleet_planner
