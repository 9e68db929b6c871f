#pragma once
/// Basic grid types of the LA-MAPF model (paper: Preliminaries, "Robot's state").
///
/// A cell is (x, y) with x the column and y the row of the grid. A robot state is a cell and
/// one of four headings: 0 = +x, 1 = -x, 2 = +y, 3 = -y. State ids are dense:
/// state = cell * 4 + heading, so per-state data lives in flat arrays of size 4 * cells.
#include <array>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace fleet_planner {

using CellId = std::int32_t;
using StateId = std::int32_t;
constexpr StateId kNoState = -1;
constexpr int kHeadings = 4;

struct Cell {
  int x = 0;
  int y = 0;
  friend bool operator==(const Cell& a, const Cell& b) { return a.x == b.x && a.y == b.y; }
  friend bool operator!=(const Cell& a, const Cell& b) { return !(a == b); }
};

/// A robot state in grid terms: cell and heading (0 = +x, 1 = -x, 2 = +y, 3 = -y).
struct GridPose {
  int x = 0;
  int y = 0;
  int heading = 0;
  friend bool operator==(const GridPose& a, const GridPose& b) {
    return a.x == b.x && a.y == b.y && a.heading == b.heading;
  }
  friend bool operator!=(const GridPose& a, const GridPose& b) { return !(a == b); }
};

/// The poses' cells lie more than `reach` apart along an axis: what two robots cover within
/// reach of their cells (their bodies, a step's sweep) cannot share a cell then.
inline bool fartherApart(const GridPose& a, const GridPose& b, int reach) {
  return std::abs(a.x - b.x) > reach || std::abs(a.y - b.y) > reach;
}

/// "(x,y,heading)", for messages.
inline std::string toString(const GridPose& p) {
  return "(" + std::to_string(p.x) + "," + std::to_string(p.y) + "," + std::to_string(p.heading) + ")";
}

/// Unit step of each heading: 0 = +x, 1 = -x, 2 = +y, 3 = -y.
constexpr std::array<Cell, kHeadings> kHeadingStep{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};
/// Heading after rotating +90 degrees (counter-clockwise in the x-y frame).
constexpr std::array<int, kHeadings> kRotateCcw{{2, 3, 1, 0}};
/// Heading after rotating -90 degrees (clockwise in the x-y frame).
constexpr std::array<int, kHeadings> kRotateCw{{3, 2, 0, 1}};
/// Heading opposite to each heading.
constexpr std::array<int, kHeadings> kOpposite{{1, 0, 3, 2}};
/// Number of quarter turns (counter-clockwise) from +x to each heading.
constexpr std::array<int, kHeadings> kQuarterTurns{{0, 2, 1, 3}};
/// The yaw of a heading (radians, 0 = +x, counter-clockwise): 0, pi, pi/2, 3 pi/2.
constexpr double headingYaw(int heading) { return kQuarterTurns[heading] * 1.5707963267948966; }

/// True for headings 0..3.
constexpr bool validHeading(int h) { return h >= 0 && h < kHeadings; }

}  // namespace fleet_planner
