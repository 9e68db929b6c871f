// Footprint discretisation against hand-computed cell sets (cells overlapped with positive area).
#include "fleet_planner/model/footprint_cells.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {
namespace {

using CellList = std::set<std::pair<int, int>>;

CellList asList(const CellSet& set) {
  CellList out;
  for (const Cell& c : set.cells()) out.insert({c.x, c.y});
  return out;
}

CellList rect(int x0, int x1, int y0, int y1) {
  CellList out;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) out.insert({x, y});
  return out;
}

TEST(FootprintCells, SmallCircleCoversOnlyItsCell) {
  for (double r : {0.1, 0.4, 0.5}) {
    FootprintCells fc(Footprint::circle(r));
    for (int h = 0; h < kHeadings; ++h) EXPECT_EQ(asList(fc.body(h)), CellList({{0, 0}})) << r;
  }
}

TEST(FootprintCells, CircleGrowsByPositiveAreaRule) {
  // r = 0.6 reaches the four neighbours (0.5 away) but not the diagonals (0.707 away).
  EXPECT_EQ(asList(FootprintCells(Footprint::circle(0.6)).body(0)),
            CellList({{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}}));
  EXPECT_EQ(asList(FootprintCells(Footprint::circle(1.0)).body(2)), rect(-1, 1, -1, 1));
  EXPECT_EQ(asList(FootprintCells(Footprint::circle(1.5)).body(1)), rect(-1, 1, -1, 1));
  // r = 1.55 adds (+-2, 0) and (0, +-2) (1.5 away) but not (2, 1) (1.58 away).
  CellList plus = rect(-1, 1, -1, 1);
  for (auto c : {std::pair{2, 0}, {-2, 0}, {0, 2}, {0, -2}}) plus.insert(c);
  EXPECT_EQ(asList(FootprintCells(Footprint::circle(1.55)).body(3)), plus);
  // r = 1.6: 5 x 5 without its four corners.
  CellList big = rect(-2, 2, -2, 2);
  for (auto c : {std::pair{2, 2}, {-2, 2}, {2, -2}, {-2, -2}}) big.erase(c);
  EXPECT_EQ(asList(FootprintCells(Footprint::circle(1.6)).body(0)), big);
}

TEST(FootprintCells, CircleRotationSweepsOnlyItsBody) {
  FootprintCells fc(Footprint::circle(1.3));
  EXPECT_EQ(asList(fc.swept(0, Action::RotateCcw)), asList(fc.body(0)));
  EXPECT_EQ(asList(fc.swept(3, Action::RotateCw)), asList(fc.body(0)));
}

TEST(FootprintCells, BlockAtAllFourHeadings) {
  // The benchmark's Block_2D -0.3 -1.1 1.1 1.1: two columns forward, three rows across.
  FootprintCells fc(Footprint::block(-0.3, -1.1, 1.1, 1.1));
  EXPECT_EQ(asList(fc.body(0)), rect(0, 1, -1, 1));   // +x
  EXPECT_EQ(asList(fc.body(1)), rect(-1, 0, -1, 1));  // -x
  EXPECT_EQ(asList(fc.body(2)), rect(-1, 1, 0, 1));   // +y
  EXPECT_EQ(asList(fc.body(3)), rect(-1, 1, -1, 0));  // -y
}

TEST(FootprintCells, BlockEdgesOnCellBordersDoNotSpill) {
  FootprintCells fc(Footprint::block(-0.5, -0.5, 1.5, 0.5));
  EXPECT_EQ(asList(fc.body(0)), CellList({{0, 0}, {1, 0}}));
  EXPECT_EQ(asList(fc.body(2)), CellList({{0, 0}, {0, 1}}));
  EXPECT_EQ(asList(fc.body(1)), CellList({{0, 0}, {-1, 0}}));
  EXPECT_EQ(asList(fc.body(3)), CellList({{0, 0}, {0, -1}}));
}

TEST(FootprintCells, BlockRotationSweep) {
  // Block [-0.5, 1.5] x [-0.5, 0.5] turning from +x to +y about its origin. The front corners
  // (radius 1.58) sweep through (2, 0), (1, 1) and (0, 2); the rear corners (radius 0.71) bulge
  // into (-1, 0) and (0, -1). (2, 1), (1, 2), (-1, 1), (1, -1) and (-1, -1) are only touched.
  FootprintCells fc(Footprint::block(-0.5, -0.5, 1.5, 0.5));
  const CellList expected{{0, 0}, {1, 0}, {0, 1}, {1, 1}, {-1, 0}, {0, -1}, {2, 0}, {0, 2}};
  EXPECT_EQ(asList(fc.swept(0, Action::RotateCcw)), expected);
  // The same turn backwards (from +y clockwise to +x) sweeps the same cells.
  EXPECT_EQ(asList(fc.swept(2, Action::RotateCw)), expected);
  // Turning from +x to -y mirrors it across the x axis.
  CellList mirrored;
  for (auto [x, y] : expected) mirrored.insert({x, -y});
  EXPECT_EQ(asList(fc.swept(0, Action::RotateCw)), mirrored);
}

TEST(FootprintCells, MovesSweepBothFootprints) {
  FootprintCells fc(Footprint::block(-0.5, -0.5, 1.5, 0.5));
  EXPECT_EQ(asList(fc.swept(0, Action::Forward)), CellList({{0, 0}, {1, 0}, {2, 0}}));
  EXPECT_EQ(asList(fc.swept(0, Action::Backward)), CellList({{-1, 0}, {0, 0}, {1, 0}}));
  EXPECT_EQ(asList(fc.swept(3, Action::Forward)), CellList({{0, 0}, {0, -1}, {0, -2}}));
  EXPECT_EQ(asList(fc.swept(1, Action::Wait)), asList(fc.body(1)));
}

TEST(FootprintCells, TrianglePolygon) {
  FootprintCells fc(Footprint::polygon({{1, 0}, {-1, 1}, {-1, -1}}));
  EXPECT_EQ(asList(fc.body(0)), CellList({{0, 0}, {1, 0}, {-1, 0}, {-1, 1}, {-1, -1}, {0, 1}, {0, -1}}));
  // At heading +y the nose points up: (x, y) -> (-y, x).
  EXPECT_EQ(asList(fc.body(2)), CellList({{0, 0}, {0, 1}, {0, -1}, {-1, -1}, {1, -1}, {-1, 0}, {1, 0}}));
}

TEST(FootprintCells, NonConvexPolygonTouchingInItsNotch) {
  // An L covering (0,0), (1,0), (0,1); cell (1,1) is only touched along the notch's edges.
  FootprintCells fc(Footprint::polygon(
      {{-0.5, -0.5}, {1.5, -0.5}, {1.5, 0.5}, {0.5, 0.5}, {0.5, 1.5}, {-0.5, 1.5}}));
  EXPECT_EQ(asList(fc.body(0)), CellList({{0, 0}, {1, 0}, {0, 1}}));
  EXPECT_EQ(asList(fc.body(2)), CellList({{0, 0}, {0, 1}, {-1, 0}}));
  EXPECT_EQ(asList(fc.body(1)), CellList({{0, 0}, {-1, 0}, {0, -1}}));
  EXPECT_EQ(asList(fc.body(3)), CellList({{0, 0}, {0, -1}, {1, 0}}));
}

TEST(FootprintCells, PolygonAwayFromOriginSweepsItsStarHull) {
  // A square wholly in front of the origin: its rotation sweep must include the cells between
  // the origin and the square (a superset of the true annular sweep), and both end poses.
  FootprintCells fc(Footprint::polygon({{1.5, -0.5}, {2.5, -0.5}, {2.5, 0.5}, {1.5, 0.5}}));
  EXPECT_EQ(asList(fc.body(0)), CellList({{2, 0}}));
  const CellList sweep = asList(fc.swept(0, Action::RotateCcw));
  // The far corner (2.5, -0.5), 2.55 from the origin, passes through (2.55, 0): cell (3, 0).
  for (auto c : {std::pair{2, 0}, {0, 2}, {1, 0}, {0, 1}, {2, 1}, {1, 2}, {2, 2}, {3, 0}}) {
    EXPECT_TRUE(sweep.count(c)) << c.first << "," << c.second;
  }
  EXPECT_FALSE(sweep.count({-1, 0}));
  EXPECT_FALSE(sweep.count({3, 1}));  // only touched at its corner (2.5, 0.5)
}

TEST(FootprintCells, SweepToleranceIgnoresShallowClipsOnly) {
  // Block [-1.3, 1.1] x [-2, 2] turning +x -> +y: its rear corner (-1.3, -2), 2.385 from the
  // origin, passes (1.686, -1.686) at -45 degrees, 0.186 deep into cell (2, -2) = [1.5, 2.5] x
  // [-2.5, -1.5]; likewise the corner (-1.3, 2) passes (-1.686, 1.686) in cell (-2, 2).
  Footprint block = Footprint::block(-1.3, -2, 1.1, 2);
  const CellList exact = asList(FootprintCells(block).swept(0, Action::RotateCcw));
  EXPECT_TRUE(exact.count({2, -2}));
  EXPECT_TRUE(exact.count({-2, 2}));
  block.sweep_tolerance = 0.18;
  EXPECT_EQ(asList(FootprintCells(block).swept(0, Action::RotateCcw)), exact);
  block.sweep_tolerance = 0.19;
  const FootprintCells tolerant(block);
  const CellList relaxed = asList(tolerant.swept(0, Action::RotateCcw));
  EXPECT_FALSE(relaxed.count({2, -2}));
  EXPECT_FALSE(relaxed.count({-2, 2}));
  for (const auto& c : relaxed) EXPECT_TRUE(exact.count(c)) << c.first << "," << c.second;
  // Both end poses stay whole, and so do moves and bodies.
  for (int h : {0, 2}) {
    for (const auto& c : asList(tolerant.body(h))) EXPECT_TRUE(relaxed.count(c));
  }
  Footprint exact_block = Footprint::block(-1.3, -2, 1.1, 2);
  for (int h = 0; h < kHeadings; ++h) {
    EXPECT_EQ(tolerant.body(h), FootprintCells(exact_block).body(h));
    EXPECT_EQ(tolerant.swept(h, Action::Forward), FootprintCells(exact_block).swept(h, Action::Forward));
  }
  EXPECT_FALSE(tolerant.sameCells(FootprintCells(exact_block)));
  EXPECT_NE(block, exact_block);
}

TEST(FootprintCells, SweepToleranceMustBeSmall) {
  for (double t : {-0.01, 0.26, std::nan("")}) {
    Footprint f = Footprint::block(-1, -1, 1, 1);
    f.sweep_tolerance = t;
    EXPECT_THROW(FootprintCells{f}, InvalidInput) << t;
  }
}

TEST(FootprintCells, OffsetPosesLieWithinTheMoveTheyAreOn) {
  // A robot between two cells, as a pose from TF puts it, covers only cells of the move's sweep
  // between them: the execution monitor relies on it to call overlaps of robots on time safe.
  const Footprint shapes[] = {Footprint::circle(2.7), Footprint::block(-3.2, -1.9, 4.1, 1.9),
                              Footprint::polygon({{-2.5, -2.5}, {3.4, 0.0}, {-2.5, 2.5}})};
  for (const Footprint& f : shapes) {
    const FootprintCells cells(f);
    for (int h = 0; h < kHeadings; ++h) {
      const double yaw = std::atan2(h == 2 ? 1.0 : h == 3 ? -1.0 : 0.0, h == 1 ? -1.0 : h == 0 ? 1.0 : 0.0);
      EXPECT_EQ(asList(footprintCellsAt(f, yaw, Eigen::Vector2d(0, 0))), asList(cells.body(h)));
      const Cell ahead = {h == 0 ? 1 : h == 1 ? -1 : 0, h == 2 ? 1 : h == 3 ? -1 : 0};
      const CellList sweep = asList(cells.swept(h, Action::Forward));
      for (double f_on : {0.1, 0.25, 0.5}) {
        const Eigen::Vector2d offset(ahead.x * f_on, ahead.y * f_on);
        const CellList at = asList(footprintCellsAt(f, yaw, offset));
        EXPECT_TRUE(std::includes(sweep.begin(), sweep.end(), at.begin(), at.end())) << h << " " << f_on;
      }
    }
  }
  // The offset counts: the block's front edge at 4.1 + 0.5 cells enters cell 5.
  EXPECT_TRUE(asList(footprintCellsAt(shapes[1], 0.0, Eigen::Vector2d(0.5, 0))).count({5, 0}));
  EXPECT_FALSE(asList(footprintCellsAt(shapes[1], 0.0, Eigen::Vector2d(0, 0))).count({5, 0}));
}

TEST(FootprintCells, SameCellsForCirclesThatDiscretiseAlike) {
  EXPECT_TRUE(FootprintCells(Footprint::circle(0.8)).sameCells(FootprintCells(Footprint::circle(1.4))));
  EXPECT_FALSE(FootprintCells(Footprint::circle(0.8)).sameCells(FootprintCells(Footprint::circle(1.6))));
}

TEST(FootprintCells, RejectsInvalidFootprints) {
  EXPECT_THROW(FootprintCells(Footprint::circle(0.0)), InvalidInput);
  EXPECT_THROW(FootprintCells(Footprint::circle(std::nan(""))), InvalidInput);
  EXPECT_THROW(FootprintCells(Footprint::block(1, -1, -1, 1)), InvalidInput);
  EXPECT_THROW(FootprintCells(Footprint::polygon({{0, 0}, {1, 0}})), InvalidInput);
  EXPECT_THROW(FootprintCells(Footprint::polygon({{0, 0}, {1, 1}, {1, 0}, {0, 1}})), InvalidInput);  // bow tie
  EXPECT_THROW(FootprintCells(Footprint::polygon({{0, 0}, {1, 0}, {2, 0}})), InvalidInput);          // flat
}

TEST(FootprintCells, SharedCellsAreBuiltOncePerFootprintAndStep) {
  Footprint block = Footprint::block(-1.2, -0.6, 1.7, 0.6);
  const auto first = sharedFootprintCells(block, 3);
  EXPECT_EQ(first, sharedFootprintCells(Footprint::block(-1.2, -0.6, 1.7, 0.6), 3));
  EXPECT_NE(first, sharedFootprintCells(block, 2));
  block.sweep_tolerance = 0.2;
  EXPECT_NE(first, sharedFootprintCells(block, 3));
  // The shared cells are those of a fresh discretisation.
  const FootprintCells fresh(Footprint::block(-1.2, -0.6, 1.7, 0.6), 3);
  EXPECT_TRUE(first->sameCells(fresh));
  EXPECT_EQ(first->step(), 3);
  EXPECT_THROW(sharedFootprintCells(Footprint::circle(0.0)), InvalidInput);
  // Beyond the 64 kept, the oldest are built again; the ones still held stay valid.
  for (int i = 1; i <= 70; ++i) sharedFootprintCells(Footprint::circle(0.1 * i), 1);
  EXPECT_NE(first, sharedFootprintCells(Footprint::block(-1.2, -0.6, 1.7, 0.6), 3));
  EXPECT_TRUE(first->sameCells(fresh));
}

TEST(FootprintCells, YawShapesAskedAgainAreEachFootprintsOwn) {
  // The shapes at a yaw and of a turn are kept once computed: asked again, for another footprint
  // or for a turn instead of a body, each is still the one of a fresh computation.
  const Footprint small = Footprint::block(-1.5, -0.5, 1.5, 0.5), big = Footprint::block(-2.0, -1.1, 2.0, 1.1);
  const Eigen::Vector2d centred(0, 0);  // with an offset: never kept, computed each time
  const CellSet small_body = footprintCellsAt(small, 0.4), small_turn = turnSweep(small, 0.4, 1.2);
  EXPECT_EQ(small_body, footprintCellsAt(small, 0.4, centred));
  EXPECT_EQ(footprintCellsAt(big, 0.4), footprintCellsAt(big, 0.4, centred));
  EXPECT_NE(footprintCellsAt(big, 0.4), small_body);
  EXPECT_EQ(footprintCellsAt(small, 0.4), small_body);
  EXPECT_EQ(turnSweep(small, 0.4, 1.2), small_turn);
  EXPECT_GT(turnSweep(big, 0.4, 1.2).size(), small_turn.size());
  EXPECT_GT(small_turn.size(), small_body.size());  // a turn is not the body at its first yaw
  // Both ends of a turn lie in it, whichever way it is asked.
  for (const auto& [from, to] : {std::pair{0.4, 1.2}, std::pair{1.2, 0.4}}) {
    const CellList turn = asList(turnSweep(small, from, to));
    for (const double yaw : {from, to}) {
      for (const auto& c : asList(footprintCellsAt(small, yaw, centred))) EXPECT_TRUE(turn.count(c)) << yaw;
    }
  }
}

}  // namespace
}  // namespace fleet_planner
