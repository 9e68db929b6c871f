#pragma once
/// Exact planar tests behind footprint discretisation (paper: Preliminaries, "Collision
/// detection"). A cell is the unit square centred on its integer coordinates; a shape covers a
/// cell when the shape and the square's interior overlap with positive area. Touching along an
/// edge or at a corner does not count. Overlaps thinner than kEps are treated as touching.
#include <vector>

#include <Eigen/Core>

namespace fleet_planner::geometry {

using Vec2 = Eigen::Vector2d;
constexpr double kEps = 1e-9;
constexpr double kPi = 3.14159265358979323846;

/// Shoelace area, positive for counter-clockwise vertex order.
double signedArea(const std::vector<Vec2>& polygon);

/// True when two edges of the closed polygon touch or cross, other than neighbours at their
/// shared vertex, or when an edge has zero length.
bool selfIntersecting(const std::vector<Vec2>& polygon);

/// Rotates p by `quarter_turns` * 90 degrees counter-clockwise (exact).
Vec2 rotateQuarter(const Vec2& p, int quarter_turns);

/// Point strictly inside a simple polygon (crossing-number rule).
bool pointInPolygon(const Vec2& p, const std::vector<Vec2>& polygon);

/// The segment [a, b] passes through the open unit square centred at c. The square tests take
/// the half-size `half` of the square (0.5: the cell; less: the cell shrunk on every side).
bool segmentEntersSquare(const Vec2& a, const Vec2& b, const Vec2& c, double half = 0.5);

/// Positive-area overlap of the unit square centred at c with a simple polygon.
bool squareOverlapsPolygon(const Vec2& c, const std::vector<Vec2>& polygon, double half = 0.5);

/// Positive-area overlap of the unit square centred at c with the disc of radius r at the origin.
bool squareOverlapsDisc(const Vec2& c, double r);

/// Positive-area overlap of the unit square centred at c with the circular sector at the origin
/// of radius r spanning the angles [a0, a1] (radians, 0 < a1 - a0 <= pi).
bool squareOverlapsSector(const Vec2& c, double r, double a0, double a1, double half = 0.5);

}  // namespace fleet_planner::geometry
