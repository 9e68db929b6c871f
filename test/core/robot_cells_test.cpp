// A robot's cells along a path (robot_cells.h): the constructor that reuses another path's yaw
// shapes gives what a fresh one gives, whether the headings agree (shapes copied) or not
// (computed again).
#include "fleet_planner/model/robot_cells.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "../test_robots.h"

namespace fleet_planner::test {
namespace {

// Every body and every sweep of `a` and `b` along `path`, one past its end included.
void expectSameCells(const RobotCells& a, const RobotCells& b, const Path& path, const ActionModel& model) {
  EXPECT_EQ(a.shapeProblem(), b.shapeProblem());
  for (int t = 0; t <= static_cast<int>(path.size()); ++t) {
    EXPECT_EQ(a.bodyAt(t), b.bodyAt(t)) << "body at " << t;
    const CellSet* sa = a.sweepAt(t, model);
    const CellSet* sb = b.sweepAt(t, model);
    ASSERT_EQ(sa == nullptr, sb == nullptr) << "sweep at " << t;
    if (sa != nullptr) {
      EXPECT_EQ(*sa, *sb) << "sweep at " << t;
    }
  }
}

TEST(RobotCells, ReusedYawShapesMatchFreshOnes) {
  Robot robot = makeRobot("r", Footprint::block(-1.6, -0.9, 1.4, 0.9), {5, 5, 0}, {9, 5, 0});
  robot.start_yaw = 0.7;
  robot.target_yaw = 1.3;
  const FootprintCells cells(robot.footprint);
  const ActionModel model{};
  // Turn from the start yaw, drive 4 cells along +x, turn to the target yaw; the second path
  // waits 3 steps on the way, the third ends on another heading (rotated once more).
  const Path first{{5, 5, 0}, {5, 5, 0}, {6, 5, 0}, {7, 5, 0}, {8, 5, 0}, {9, 5, 0}, {9, 5, 0}};
  const Path waits{{5, 5, 0}, {5, 5, 0}, {6, 5, 0}, {6, 5, 0}, {6, 5, 0}, {6, 5, 0},
                   {7, 5, 0}, {8, 5, 0}, {9, 5, 0}, {9, 5, 0}};
  const Path turned{{5, 5, 0}, {5, 5, 0}, {6, 5, 0}, {7, 5, 0}, {8, 5, 0}, {9, 5, 0}, {9, 5, 2}, {9, 5, 2}};
  const RobotCells shapes(robot, cells, first);
  ASSERT_EQ(shapes.shapeProblem(), "");
  for (const Path* path : {&first, &waits, &turned}) {
    const RobotCells fresh(robot, cells, *path);
    const RobotCells reused(robot, shapes, *path);
    ASSERT_EQ(fresh.shapeProblem(), "");
    expectSameCells(fresh, reused, *path, model);
  }
  // The third path's last turn starts from another heading than the first's: its shape had to
  // be computed again, not copied.
  const RobotCells fresh_turned(robot, cells, turned);
  ASSERT_NE(fresh_turned.sweepAt(6, model), nullptr);
  EXPECT_NE(*fresh_turned.sweepAt(6, model), *shapes.sweepAt(5, model));
}

TEST(RobotCells, EveryCellLiesWithinTheReach) {
  Robot robot = makeRobot("r", Footprint::block(-1.6, -0.9, 1.4, 0.9), {5, 5, 0}, {9, 9, 2});
  robot.start_yaw = 0.7;
  robot.target_yaw = 2.1;
  const FootprintCells cells(robot.footprint, 2);
  const ActionModel model{false, 2};
  // Turn from the start yaw, two moves of the lattice step, a rotation, two moves, the turn to
  // the target yaw.
  const Path path{{5, 5, 0}, {5, 5, 0}, {7, 5, 0}, {9, 5, 0}, {9, 5, 2}, {9, 7, 2}, {9, 9, 2}, {9, 9, 2}};
  const RobotCells along(robot, cells, path);
  ASSERT_EQ(along.shapeProblem(), "");
  int farthest = 0;
  for (int t = 0; t <= static_cast<int>(path.size()); ++t) {
    const CellSet* sweep = along.sweepAt(t, model);
    ASSERT_NE(sweep, nullptr) << t;
    for (const CellSet* set : {&along.bodyAt(t), sweep}) {
      for (const Cell& c : set->cells()) {
        EXPECT_LE(std::max(std::abs(c.x), std::abs(c.y)), along.reach()) << "step " << t;
        farthest = std::max({farthest, std::abs(c.x), std::abs(c.y)});
      }
    }
  }
  // A bound, and a close one (a backward move, not on this path, sweeps one cell farther).
  EXPECT_LE(along.reach(), farthest + 1);
}

}  // namespace
}  // namespace fleet_planner::test
