// The planning lattice (lattice.h): plans on lattices of 2-8 cells are valid on the map's own
// cells, connections put any start and target on a robot's lattice, a door as wide as a robot
// stays open when a lattice line passes through it, the same input gives the same plan, and a
// robot that needs no connection does not wait for another robot's.
#include "fleet_planner/planning/lattice.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/model/robot_cells.h"
#include "fleet_planner/planning/plan_fleet.h"
#include "fleet_planner/runtime/random.h"
#include "test_maps.h"
#include "lattice_worlds.h"
#include "test_robots.h"
#include "valid_on_cells.h"

namespace fleet_planner::test {
namespace {

TEST(Lattice, DefaultStepIsAThirdOfTheNarrowestRobot) {
  Instance fleet;
  fleet.robots = {box("wide", 20, 12, {0, 0, 0}, {0, 0, 0}), box("narrow", 9, 7, {0, 0, 0}, {0, 0, 0})};
  EXPECT_EQ(defaultLatticeStep(fleet), 2);  // 7 cells / 3
  fleet.robots = {makeRobot("disc", Footprint::circle(9.0), {0, 0, 0}, {0, 0, 0})};
  EXPECT_EQ(defaultLatticeStep(fleet), 6);
  fleet.robots = {makeRobot("benchmark", Footprint::circle(1.5), {0, 0, 0}, {0, 0, 0})};
  EXPECT_EQ(defaultLatticeStep(fleet), 1);
}

TEST(Lattice, PlansOnLatticesOfTwoToEightCellsAreValidOnTheMapsCells) {
  int worlds = 0, on_lattice = 0;
  for (std::uint64_t seed = 1; seed <= 8 && worlds < 4; ++seed) {
    const RandomWorld world(6, seed);
    ASSERT_GE(world.instance.robots.size(), 4u);
    if (!planFleet(world.map, world.instance, onLattice(1)).success()) continue;  // no plan at all
    ++worlds;
    for (int step = 2; step <= 8; step += 2) {
      const PlanningResult r = planFleet(world.map, world.instance, onLattice(step));
      EXPECT_TRUE(validOnCells(world.map, world.instance, r)) << "seed " << seed << " step " << step;
      if (r.lattice_step == step) ++on_lattice;
      // A coarser lattice given up is always said, with the reason.
      EXPECT_EQ(r.lattice_step == step, r.lattice_notes.empty()) << "seed " << seed << " step " << step;
      for (const std::string& note : r.lattice_notes) std::cout << "seed " << seed << ": " << note << "\n";
    }
  }
  EXPECT_EQ(worlds, 4);
  EXPECT_GE(on_lattice, 8);  // of 16: most fleets plan on the lattice asked for
}

TEST(Lattice, ConnectionsPutAStartAndATargetOffTheLatticeOnIt) {
  // On a lattice of 4 through the start, the target is 3 cells off in x and 2 in y.
  const GridMap map = freeMap(40, 24);
  Instance instance;
  instance.robots = {box("r", 6, 4, {6, 6, 0}, {29, 16, 2})};
  PlanningOptions o = onLattice(4);
  o.cell_steps = false;  // the moves as the lattice made them
  const PlanningResult r = planFleet(map, instance, o);
  ASSERT_TRUE(validOnCells(map, instance, r));
  EXPECT_EQ(r.lattice_step, 4);
  const Path& path = r.plan.paths[0];
  int short_moves = 0, long_moves = 0;
  for (std::size_t t = 0; t + 1 < path.size(); ++t) {
    const int length = path[t].heading == path[t + 1].heading ? moveLength(path[t], path[t + 1]) : 0;
    short_moves += length > 0 && length < 4;
    long_moves += length == 4;
  }
  EXPECT_GE(short_moves, 1);
  EXPECT_GE(long_moves, 3);
}

TEST(Lattice, ADoorAsWideAsTheRobotStaysOpenWhenALatticeLinePassesThroughIt) {
  // A wall at x = 20 with a door 5 cells wide (y = 10..14); the robot covers 5 cells across.
  std::vector<std::string> rows(25, std::string(40, '.'));
  for (int y = 0; y < 25; ++y) {
    if (y < 10 || y > 14) rows[y][20] = '@';
  }
  const GridMap map = mapFromRows(rows);
  Instance instance;
  instance.robots = {box("r", 5, 5, {4, 12, 0}, {35, 12, 0})};  // the lattice line y = 12 runs through the door
  const PlanningResult r = planFleet(map, instance, onLattice(4));
  ASSERT_TRUE(validOnCells(map, instance, r));
  EXPECT_EQ(r.lattice_step, 4) << (r.lattice_notes.empty() ? "" : r.lattice_notes.front());
}

/// Walls at x = 20 and x = 30 with doors 5 cells wide from y = `door` (and from y = `door2`),
/// closed below `bottom` (open rows under it: a way round); the map is `height` cells high.
GridMap doorsMap(int height, int door, int door2, int bottom) {
  std::vector<std::string> rows(height, std::string(48, '.'));
  for (int y = 0; y < height; ++y) {
    if ((y < door || y > door + 4) && y < bottom) rows[y][20] = '@';
    if ((y < door2 || y > door2 + 4) && y < bottom) rows[y][30] = '@';
  }
  return mapFromRows(rows);
}

TEST(Lattice, AConnectionPicksTheLatticeOffsetThatKeepsADoorOpen) {
  // The robot stands on y = 11; lattice lines through it (y = 11 + 4k) miss the door (it needs
  // y = 12), and the way round the walls' ends is long. Its connections move it one cell onto
  // the lattice through the door and back: the way straight through costs the 32 cells / 4 of
  // the moves and a few steps of connections.
  const GridMap map = doorsMap(32, 10, 10, 23);
  Instance instance;
  instance.robots = {box("r", 5, 5, {4, 11, 0}, {36, 11, 0})};
  PlanningOptions o = onLattice(4);
  o.cell_steps = false;  // its cost in the lattice's steps
  const PlanningResult r = planFleet(map, instance, o);
  ASSERT_TRUE(validOnCells(map, instance, r));
  EXPECT_EQ(r.lattice_step, 4);
  EXPECT_TRUE(r.lattice_notes.empty()) << (r.lattice_notes.empty() ? "" : r.lattice_notes.front());
  const int cost = pathCost(r.plan.paths[0], instance.robots[0].target);
  EXPECT_LE(cost, 16) << "a way round the walls";
}

TEST(Lattice, ARobotThatTheLatticeCannotServeIsNamedAndPlannedOnAFinerOne) {
  // Two doors in a row, at y = 10..14 and y = 11..15: a robot 5 cells across needs y = 12 in the
  // first and y = 13 in the second, and a lattice of 4 cannot shift it by one cell between them:
  // the plan is made on a finer lattice and the reason names the robot.
  const GridMap map = doorsMap(25, 10, 11, 25);
  Instance instance;
  instance.robots = {box("r", 5, 5, {4, 11, 0}, {35, 11, 0})};
  const PlanningResult r = planFleet(map, instance, onLattice(4));
  ASSERT_TRUE(validOnCells(map, instance, r));
  EXPECT_LT(r.lattice_step, 4);
  ASSERT_FALSE(r.lattice_notes.empty());
  EXPECT_NE(r.lattice_notes.front().find("step 4"), std::string::npos) << r.lattice_notes.front();
  EXPECT_NE(r.lattice_notes.front().find("'r'"), std::string::npos) << r.lattice_notes.front();
}

// The same plan again, and on two threads (the connections, the distance tables and the
// parking plans are made on both).
TEST(Lattice, SameInputSamePlan) {
  const RandomWorld world(6, 7);
  const PlanningResult a = planFleet(world.map, world.instance, onLattice(3));
  const PlanningResult b = planFleet(world.map, world.instance, onLattice(3));
  PlanningOptions two = onLattice(3);
  two.threads = 2;
  const PlanningResult c = planFleet(world.map, world.instance, two);
  ASSERT_TRUE(validOnCells(world.map, world.instance, a));
  EXPECT_EQ(a.lattice_step, b.lattice_step);
  EXPECT_EQ(a.plan.paths, b.plan.paths);
  EXPECT_EQ(a.plan.paths, c.plan.paths);
}

// pathsMeet, which skips the steps at which the robots are farther apart than their reaches,
// answers as a check of every step's cells does: a robot at a yaw turning onto the x axis and
// driving along it, another crossing its way or waiting beside it at every offset around it.
TEST(Lattice, PathsMeetAsACheckOfEveryStepSays) {
  const ActionModel model{false, 2};
  Robot a = makeRobot("a", Footprint::block(-1.6, -0.9, 1.4, 0.9), {10, 10, 0}, {16, 10, 0});
  a.start_yaw = 0.5;
  const Robot b = makeRobot("b", Footprint::circle(1.2), {0, 0, 2}, {0, 0, 2});
  const auto cells_a = sharedFootprintCells(a.footprint, 2), cells_b = sharedFootprintCells(b.footprint, 2);
  const Path pa{{10, 10, 0}, {10, 10, 0}, {12, 10, 0}, {14, 10, 0}, {16, 10, 0}};
  const RobotCells along_a(a, *cells_a, pa);
  ASSERT_EQ(along_a.shapeProblem(), "");
  int met = 0, apart = 0;
  for (int dx = -12; dx <= 12; ++dx) {
    for (int dy = -8; dy <= 8; dy += 2) {
      for (const bool crossing : {false, true}) {
        Path pb{{16 + dx, 10 + dy, 2}};
        if (crossing) pb = {{12 + dx, 6 + dy, 2}, {12 + dx, 8 + dy, 2}, {12 + dx, 10 + dy, 2}, {12 + dx, 12 + dy, 2}};
        const RobotCells along_b(b, *cells_b, pb);
        for (const int from : {0, 2}) {
          bool every_step = false;
          const int end = static_cast<int>(std::max(pa.size(), pb.size()));
          for (int u = from; u < end && !every_step; ++u) {
            const GridPose &p = stateAt(pa, u), &q = stateAt(pb, u);
            every_step = CellSet::overlap(*along_a.sweepAt(u, model), {p.x, p.y}, *along_b.sweepAt(u, model), {q.x, q.y});
          }
          every_step = every_step || CellSet::overlap(along_a.bodyAt(end), {pa.back().x, pa.back().y},
                                                      along_b.bodyAt(end), {pb.back().x, pb.back().y});
          EXPECT_EQ(pathsMeet(along_a, pa, along_b, pb, from, model), every_step)
              << "offset " << dx << "," << dy << (crossing ? " crossing" : " waiting") << " from " << from;
          (every_step ? met : apart) += 1;
        }
      }
    }
  }
  EXPECT_GT(met, 50);  // both answers are common
  EXPECT_GT(apart, 50);
}

TEST(AnyYaw, StartsAndTargetsAtAnyYawAreTurnedFromAndToOnTheLatticeAndOff) {
  const GridMap map = freeMap(48, 30);
  Instance instance;
  instance.robots = {box("a", 7, 5, {8, 8, 0}, {38, 20, 2}), box("b", 6, 4, {38, 8, 1}, {8, 22, 0}),
                     box("c", 5, 5, {24, 13, 2}, {24, 23, 2})};
  instance.robots[0].start_yaw = 0.61;
  instance.robots[0].target_yaw = 2.3;
  instance.robots[1].start_yaw = -2.9;
  instance.robots[2].target_yaw = -0.4;
  for (int step : {1, 3}) {
    const PlanningResult r = planFleet(map, instance, onLattice(step));
    ASSERT_TRUE(validOnCells(map, instance, r)) << "step " << step;
    EXPECT_EQ(r.lattice_step, step);
    const Path& a = r.plan.paths[0];
    EXPECT_EQ(a[0], a[1]) << "the first step turns from the start yaw";
    EXPECT_EQ(a[a.size() - 2], a.back()) << "the last step turns to the target yaw";
    EXPECT_GT(r.metrics.soc, 0);
  }
}

TEST(AnyYaw, ARobotLeavesAtOnceWhileAnotherTurnsFromItsStartYaw) {
  // a turns from its start yaw before it drives; b, far from it, starts on its lattice and
  // needs no turn: it drives at once, not after a's turn (the connections are retimed).
  const GridMap map = freeMap(60, 30);
  Instance instance;
  instance.robots = {box("a", 6, 4, {8, 8, 0}, {20, 20, 0}), box("b", 6, 4, {50, 8, 1}, {50, 23, 1})};
  instance.robots[0].start_yaw = 2.4;
  const PlanningResult r = planFleet(map, instance, onLattice(3));
  ASSERT_TRUE(validOnCells(map, instance, r));
  const Path& a = r.plan.paths[0];
  const Path& b = r.plan.paths[1];
  ASSERT_GE(a.size(), 3u);
  ASSERT_GE(b.size(), 2u);
  EXPECT_EQ(a[0], a[1]) << "a's first step turns from its start yaw";
  EXPECT_NE(b[0], b[1]) << "b waits at its start";
}

TEST(AnyYaw, AStartWhoseTurnHitsAWallIsNamedWithTheCell) {
  // A stick 6 cells long standing at 45 degrees, with a blocked cell where each of the two grid
  // headings next to its yaw would put its front end: it stands free but can turn to neither.
  std::vector<std::string> rows(20, std::string(20, '.'));
  rows[10][13] = '@';  // (13, 10): its front end at heading +x
  rows[13][10] = '@';  // (10, 13): its front end at heading +y
  const GridMap map = mapFromRows(rows);
  Instance instance;
  instance.robots = {makeRobot("stick", Footprint::block(-3.0, -0.2, 3.0, 0.2), {10, 10, 0}, {4, 4, 0})};
  instance.robots[0].start_yaw = 0.785398;
  const PlanningResult r = planFleet(map, instance, onLattice(1));
  EXPECT_EQ(r.status, SolveStatus::InvalidInput) << r.reason;
  ASSERT_EQ(r.precheck.problems.size(), 1u) << statusName(r.status) << ": " << r.reason;
  EXPECT_EQ(r.precheck.problems[0].kind, RobotProblem::Kind::InvalidStart);
  EXPECT_NE(r.reason.find("'stick'"), std::string::npos) << r.reason;
  EXPECT_NE(r.reason.find("blocked cell (1"), std::string::npos) << r.reason;
  // Without the walls it turns and plans.
  EXPECT_TRUE(validOnCells(freeMap(20, 20), instance, planFleet(freeMap(20, 20), instance, onLattice(1))));
}

}  // namespace
}  // namespace fleet_planner::test
