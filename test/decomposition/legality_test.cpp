// The legality checker of a decomposition (paper: "Decomposition of instance", the simplified
// scenario) on tiny hand-made maps: legal orders accepted, illegal orders and bad coverage
// rejected with the failing robot, subproblem and reason.
#include "fleet_planner/decomposition/legality.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "test_maps.h"
#include "test_robots.h"
#include "fleet_planner/model/footprint_cells.h"

namespace fleet_planner {
namespace {

using test::mapFromRows;

Robot robot(const std::string& id, GridPose start, GridPose target, Footprint f = Footprint::circle(0.4)) {
  return test::makeRobot(id, std::move(f), start, target);
}

struct Fixture {
  GridMap map;
  Instance instance;
  FleetGraphs graphs;
  Fixture(GridMap m, std::vector<Robot> robots)
      : map(std::move(m)), instance{std::move(robots), ""}, graphs(map, test::footprintsOf(instance)) {}
  LegalityReport check(const std::vector<std::vector<int>>& subproblems) const {
    return checkLegality(instance, graphs, subproblems);
  }
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The paper's Figure 1 B on a plus-shaped map: a1 (1,2) -> (1,1) needs nothing of a2, a2 (0,1)
// -> (2,1) must cross a1's target, so a2 must be solved first.
Fixture figureB() {
  return Fixture(mapFromRows({"@.@", "...", "@.@"}),
                 {robot("a1", {1, 2, 3}, {1, 1, 3}), robot("a2", {0, 1, 0}, {2, 1, 0})});
}

TEST(Legality, TwoLevelsInTheRightOrderAreLegal) {
  const Fixture f = figureB();
  const LegalityReport r = f.check({{1}, {0}});
  EXPECT_TRUE(r.legal) << r.message;
  EXPECT_EQ(r.subproblem, -1);
  EXPECT_EQ(r.robot, -1);
  EXPECT_TRUE(r.message.empty());
}

TEST(Legality, TwoLevelsInTheWrongOrderAreIllegal) {
  const Fixture f = figureB();
  const LegalityReport r = f.check({{0}, {1}});
  EXPECT_FALSE(r.legal);
  EXPECT_EQ(r.subproblem, 1);
  EXPECT_EQ(r.robot, 1);
  EXPECT_TRUE(contains(r.message, "'a2'")) << r.message;
  EXPECT_TRUE(contains(r.message, "subproblem 1")) << r.message;
  EXPECT_TRUE(contains(r.message, "no path")) << r.message;
}

TEST(Legality, OneSubproblemIgnoresConflictsInsideIt) {
  // Robots of the same subproblem do not block each other in the simplified scenario.
  const Fixture f = figureB();
  const LegalityReport r = f.check({{0, 1}});
  EXPECT_TRUE(r.legal) << r.message;
}

TEST(Legality, EarlierRobotsStandAtTargetsLaterOnesAtStarts) {
  // Corridor: A (0,0) -> (2,0) ends where B starts; B (2,0) -> (4,0).
  // B first: B leaves (2,0) avoiding A's start; then A avoids B's target (4,0). Legal.
  // A first: A's target is covered by B, still at its start. A swapped convention (earlier at
  // starts, later at targets) gets both answers wrong.
  const Fixture f(mapFromRows({"....."}), {robot("A", {0, 0, 0}, {2, 0, 0}), robot("B", {2, 0, 0}, {4, 0, 0})});
  const LegalityReport good = f.check({{1}, {0}});
  EXPECT_TRUE(good.legal) << good.message;
  const LegalityReport bad = f.check({{0}, {1}});
  EXPECT_FALSE(bad.legal);
  EXPECT_EQ(bad.subproblem, 0);
  EXPECT_EQ(bad.robot, 0);
  EXPECT_TRUE(contains(bad.message, "'A'")) << bad.message;
  EXPECT_TRUE(contains(bad.message, "subproblem 0")) << bad.message;
  EXPECT_TRUE(contains(bad.message, "target is covered")) << bad.message;
}

TEST(Legality, StartCoveredByAnotherSubproblemIsReported) {
  // Overlapping starts (not a valid instance, but the checker must say what is wrong).
  const Fixture f(mapFromRows({"....."}), {robot("A", {0, 0, 0}, {2, 0, 0}), robot("B", {0, 0, 2}, {4, 0, 0})});
  const LegalityReport r = f.check({{0}, {1}});
  EXPECT_FALSE(r.legal);
  EXPECT_EQ(r.subproblem, 0);
  EXPECT_EQ(r.robot, 0);
  EXPECT_TRUE(contains(r.message, "'A'")) << r.message;
  EXPECT_TRUE(contains(r.message, "start is covered")) << r.message;
}

TEST(Legality, DetoursAroundBlockedCellsAreFound) {
  // A (0,1) -> (2,1); B stands at the centre (1,1) until later. A goes round by row 0 or 2
  // (turns cost steps but are allowed): legal.
  const Fixture f(mapFromRows({"...", "...", "..."}),
                  {robot("A", {0, 1, 0}, {2, 1, 0}), robot("B", {1, 1, 2}, {1, 2, 2})});
  const LegalityReport r = f.check({{0}, {1}});
  EXPECT_TRUE(r.legal) << r.message;
  // Without the detour rows the same order is illegal.
  const Fixture g(mapFromRows({"@@@", "...", "@.@"}),
                  {robot("A", {0, 1, 0}, {2, 1, 0}), robot("B", {1, 1, 2}, {1, 2, 2})});
  const LegalityReport s = g.check({{0}, {1}});
  EXPECT_FALSE(s.legal);
  EXPECT_EQ(s.robot, 0);
  EXPECT_TRUE(contains(s.message, "no path")) << s.message;
}

TEST(Legality, SweptCellsCountNotOnlyFootprints) {
  // Block [-0.4,1.2]x[-0.4,0.4]: covers its cell and the one ahead. Turning +90 degrees at
  // (2,2) from +x to +y also sweeps (3,3), which neither end pose covers. The map leaves only
  // the cells of that turn free, so the turn is A's only way to its target. B stands on (3,3)
  // until later: a checker that tested footprints only would accept A first; it is illegal.
  const Footprint block = Footprint::block(-0.4, -0.4, 1.2, 0.4);
  const FootprintCells cells(block);
  ASSERT_TRUE(cells.swept(0, Action::RotateCcw).contains(1, 1));
  ASSERT_FALSE(cells.body(0).contains(1, 1));
  ASSERT_FALSE(cells.body(2).contains(1, 1));
  const GridMap map = mapFromRows({"@@@@@", "@@.@@", "@....", "@@..@", "@@@@@"});
  //                                          y=1: (2,1)   y=2: (1..4,2)   y=3: (2,3) (3,3)
  const Fixture f(map, {robot("A", {2, 2, 0}, {2, 2, 2}, block), robot("B", {3, 3, 3}, {4, 2, 0})});
  const LegalityReport r = f.check({{0}, {1}});
  EXPECT_FALSE(r.legal);
  EXPECT_EQ(r.subproblem, 0);
  EXPECT_EQ(r.robot, 0);
  EXPECT_TRUE(contains(r.message, "no path")) << r.message;
  // Together (nothing blocks the sweep) the turn is allowed: the path exists.
  const LegalityReport together = f.check({{0, 1}});
  EXPECT_TRUE(together.legal) << together.message;
}

TEST(Legality, EveryRobotMustBeCoveredExactlyOnce) {
  const Fixture f = figureB();
  const LegalityReport missing = f.check({{1}});
  EXPECT_FALSE(missing.legal);
  EXPECT_EQ(missing.robot, 0);
  EXPECT_TRUE(contains(missing.message, "'a1'")) << missing.message;
  EXPECT_TRUE(contains(missing.message, "no subproblem")) << missing.message;

  const LegalityReport twice = f.check({{1}, {0, 1}});
  EXPECT_FALSE(twice.legal);
  EXPECT_EQ(twice.robot, 1);
  EXPECT_TRUE(contains(twice.message, "'a2'")) << twice.message;

  const LegalityReport twice_in_one = f.check({{1, 1}, {0}});
  EXPECT_FALSE(twice_in_one.legal);
  EXPECT_EQ(twice_in_one.robot, 1);
  EXPECT_TRUE(contains(twice_in_one.message, "'a2'")) << twice_in_one.message;

  const LegalityReport out_of_range = f.check({{1}, {0, 2}});
  EXPECT_FALSE(out_of_range.legal);
  EXPECT_TRUE(contains(out_of_range.message, "robot index 2")) << out_of_range.message;

  const LegalityReport empty = f.check({{1}, {}, {0}});
  EXPECT_FALSE(empty.legal);
  EXPECT_EQ(empty.subproblem, 1);

  const LegalityReport none = f.check({});
  EXPECT_FALSE(none.legal);
}

TEST(Legality, NoRobotsNoSubproblemsIsLegal) {
  const Fixture f(mapFromRows({"..."}), {});
  EXPECT_TRUE(f.check({}).legal);
}

}  // namespace
}  // namespace fleet_planner
