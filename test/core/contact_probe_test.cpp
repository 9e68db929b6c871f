// Contact probes (contact_probe.h): a set meets a thick 4-connected set exactly when its probe does.
#include "fleet_planner/model/contact_probe.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "fleet_planner/model/footprint_cells.h"
#include "fleet_planner/runtime/random.h"

namespace fleet_planner {
namespace {

CellSet rectangle(int x0, int x1, int y0, int y1) {
  std::vector<Cell> cells;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) cells.push_back({x, y});
  return CellSet::fromCells(cells);
}

TEST(ContactProbe, LargestSquareAndConnectivity) {
  EXPECT_EQ(largestSquare(CellSet()), 0);
  EXPECT_EQ(largestSquare(rectangle(-3, 4, 0, 2)), 3);
  // An L of two 2-wide bars: no 3 x 3 square.
  const CellSet l = rectangle(0, 5, 0, 1).unionWith(rectangle(0, 1, 0, 5), {0, 0});
  EXPECT_EQ(largestSquare(l), 2);
  EXPECT_TRUE(fourConnected(l));
  EXPECT_TRUE(fourConnected(CellSet()));
  // Two cells touching at a corner only.
  EXPECT_FALSE(fourConnected(CellSet::fromCells({{0, 0}, {1, 1}})));
  EXPECT_FALSE(fourConnected(rectangle(0, 1, 0, 1).unionWith(rectangle(4, 5, 0, 1), {0, 0})));
}

TEST(ContactProbe, KeepsTheBorderAndAGridOfTheInside) {
  const CellSet body = rectangle(-9, 8, -6, 5);  // 18 x 12
  const CellSet probe = contactProbe(body, 4);
  EXPECT_EQ(contactProbe(body, 1), body);
  // 56 border cells and the inner cells on the pitch-4 grid (x in {-8, -4, 0, 4}, y in {-4, 0, 4}).
  EXPECT_EQ(probe.size(), 56u + 12u);
  for (const Cell& c : probe.cells()) EXPECT_TRUE(body.contains(c.x, c.y));
  EXPECT_FALSE(probe.contains(-7, -4));
  EXPECT_TRUE(probe.contains(-8, -4));
}

// Bodies and sweeps of real-sized robots (a TurtleBot-like disc, a MiR-like block, a PR2-like
// pentagon) at lattice step 2: every placement of one against another meets exactly when the
// probe of the first, at the pitch of the fleet's smallest square, meets the second.
TEST(ContactProbe, FindsEveryContactOfTheFleetsSweeps) {
  const std::vector<FootprintCells> fleet = {
      FootprintCells(Footprint::circle(3.0), 2), FootprintCells(Footprint::block(-8.9, -5.8, 8.9, 5.8), 2),
      FootprintCells(Footprint::polygon({{-6.5, -6.5}, {-6.5, 6.5}, {6.5, 6.5}, {9.2, 0.0}, {6.5, -6.5}}), 2)};
  std::vector<const CellSet*> sets;
  int side = 1 << 20;
  for (const FootprintCells& fc : fleet) {
    for (int h = 0; h < kHeadings; ++h) {
      side = std::min(side, largestSquare(fc.body(h)));
      for (int act = 0; act < kActions; ++act) {
        sets.push_back(&fc.swept(h, static_cast<Action>(act)));
        ASSERT_TRUE(fourConnected(*sets.back()));
      }
    }
  }
  ASSERT_GE(side, 3);
  Rng rng(7);
  int contacts = 0, checked = 0;
  for (const CellSet* s : sets) {
    const CellSet probe = contactProbe(*s, side);
    EXPECT_LT(probe.size(), s->size());
    for (const CellSet* t : sets) {
      for (int k = 0; k < 40; ++k) {
        const Cell at{static_cast<int>(rng.uniformInt(-20, 20)), static_cast<int>(rng.uniformInt(-20, 20))};
        const bool meets = CellSet::overlap(*s, {0, 0}, *t, at);
        EXPECT_EQ(CellSet::overlap(probe, {0, 0}, *t, at), meets);
        contacts += meets ? 1 : 0;
        ++checked;
      }
    }
  }
  // Both answers occur often, including sets inside one another.
  EXPECT_GT(contacts, checked / 4);
  EXPECT_LT(contacts, checked);
}

}  // namespace
}  // namespace fleet_planner
