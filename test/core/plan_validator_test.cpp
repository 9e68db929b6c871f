// The independent plan validator: each kind of violation caught on a crafted plan, valid plans
// accepted.
#include "fleet_planner/model/plan_validator.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/runtime/random.h"
#include "test_maps.h"
#include "test_robots.h"

namespace fleet_planner {
namespace {

using test::freeMap;
using test::mapFromRows;
using Kind = Violation::Kind;

Robot robot(const std::string& id, Footprint f, GridPose start, GridPose target) {
  return test::makeRobot(id, std::move(f), start, target);
}
using test::dot;

Violation check(const GridMap& map, const std::vector<Robot>& robots, const std::vector<Path>& paths,
                ActionModel model = {}) {
  Instance instance;
  instance.robots = robots;
  Plan plan;
  plan.paths = paths;
  return validatePlan(map, instance, plan, model).violation;
}

TEST(PlanValidator, AcceptsAValidPlan) {
  // a crosses the corridor while b waits for it, then b follows.
  const GridMap map = freeMap(5, 2);
  const auto v = check(map, {dot("a", {0, 0, 0}, {4, 0, 0}), dot("b", {2, 1, 3}, {2, 0, 3})},
                       {{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}},
                        {{2, 1, 3}, {2, 1, 3}, {2, 1, 3}, {2, 1, 3}, {2, 0, 3}}});
  EXPECT_EQ(v.kind, Kind::None) << v.message;
}

TEST(PlanValidator, ChangesAreCheckedAgainstEveryoneAndOnlyThey) {
  // a and b meet head-on (a conflict between them); c drives alone on the row below.
  const GridMap map = freeMap(5, 2);
  Instance instance;
  instance.robots = {dot("a", {0, 0, 0}, {3, 0, 0}), dot("b", {4, 0, 1}, {1, 0, 1}), dot("c", {0, 1, 0}, {4, 1, 0})};
  Plan plan;
  plan.paths = {{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}},
                {{4, 0, 1}, {3, 0, 1}, {2, 0, 1}, {1, 0, 1}},
                {{0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {3, 1, 0}, {4, 1, 0}}};
  EXPECT_FALSE(validatePlan(map, instance, plan).valid());
  EXPECT_TRUE(validatePlanChanges(map, instance, plan, {}, {2}).valid());  // c meets nobody
  EXPECT_EQ(validatePlanChanges(map, instance, plan, {}, {1}).violation.kind, Kind::VertexConflict);
  // Before `from` nothing is checked: a and b meet at t = 2, the past from t = 3 on.
  EXPECT_TRUE(validatePlanChanges(map, instance, plan, {}, {1}, 3).valid());
  EXPECT_EQ(validatePlanChanges(map, instance, plan, {}, {1}, 2).violation.kind, Kind::VertexConflict);
  // c's new path ends where a arrives at t = 3: found although a is unchanged.
  plan.paths[2] = {{0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {3, 1, 0}, {3, 1, 3}, {3, 0, 3}};
  instance.robots[2].target = {3, 0, 3};
  EXPECT_FALSE(validatePlanChanges(map, instance, plan, {}, {2}).valid());
}

TEST(PlanValidator, AcceptsSinglePoseAndStaggeredPaths) {
  const GridMap map = freeMap(4, 4);
  const auto v = check(map, {dot("a", {0, 0, 0}, {0, 0, 0}), dot("b", {3, 3, 1}, {1, 3, 1})},
                       {{{0, 0, 0}}, {{3, 3, 1}, {2, 3, 1}, {1, 3, 1}}});
  EXPECT_EQ(v.kind, Kind::None) << v.message;
}

TEST(PlanValidator, StructuralViolations) {
  const GridMap map = freeMap(4, 1);
  const auto a = dot("a", {0, 0, 0}, {2, 0, 0});
  EXPECT_EQ(check(map, {a}, {}).kind, Kind::WrongPathCount);
  EXPECT_EQ(check(map, {a}, {{}}).kind, Kind::EmptyPath);
  EXPECT_EQ(check(map, {a}, {{{1, 0, 0}, {2, 0, 0}}}).kind, Kind::WrongStart);
  const auto v = check(map, {a}, {{{0, 0, 0}, {1, 0, 0}}});
  EXPECT_EQ(v.kind, Kind::WrongTarget);
  EXPECT_EQ(v.robot, 0);
  EXPECT_NE(v.message.find("robot 'a'"), std::string::npos) << v.message;
}

TEST(PlanValidator, IllegalActions) {
  const GridMap map = freeMap(4, 2);
  const auto a = dot("a", {0, 0, 0}, {2, 0, 0});
  auto v = check(map, {a}, {{{0, 0, 0}, {2, 0, 0}}});  // jumps two cells
  EXPECT_EQ(v.kind, Kind::IllegalAction);
  EXPECT_EQ(v.time, 0);
  v = check(map, {a}, {{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {2, 0, 0}}});  // sideways
  EXPECT_EQ(v.kind, Kind::IllegalAction);
  v = check(map, {dot("a", {0, 0, 0}, {0, 0, 1})}, {{{0, 0, 0}, {0, 0, 1}}});  // 180-degree turn
  EXPECT_EQ(v.kind, Kind::IllegalAction);
  // Backward moves only with the option.
  const auto b = dot("b", {1, 0, 0}, {0, 0, 0});
  EXPECT_EQ(check(map, {b}, {{{1, 0, 0}, {0, 0, 0}}}).kind, Kind::IllegalAction);
  ActionModel backward;
  backward.allow_backward = true;
  EXPECT_EQ(check(map, {b}, {{{1, 0, 0}, {0, 0, 0}}}, backward).kind, Kind::None);
}

TEST(PlanValidator, StateInObstacle) {
  const GridMap map = mapFromRows({"..@.."});
  const auto v = check(map, {dot("a", {0, 0, 0}, {4, 0, 0})},
                       {{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}}});
  EXPECT_EQ(v.kind, Kind::StateInObstacle);
  EXPECT_EQ(v.time, 2);
  // A footprint hanging off the map is in an obstacle too.
  const auto w = check(freeMap(3, 3), {robot("w", Footprint::circle(0.6), {0, 1, 0}, {0, 1, 0})},
                       {{{0, 1, 0}}});
  EXPECT_EQ(w.kind, Kind::StateInObstacle);
}

TEST(PlanValidator, SweepInObstacle) {
  // Both end poses of the turn are free; the front corner passes over (3, 2).
  const GridMap map = mapFromRows({".....", ".....", "...@.", ".....", "....."});
  const auto v = check(map, {robot("b", Footprint::block(-0.5, -0.5, 1.5, 0.5), {1, 2, 0}, {1, 2, 2})},
                       {{{1, 2, 0}, {1, 2, 2}}});
  EXPECT_EQ(v.kind, Kind::SweepInObstacle);
  EXPECT_EQ(v.time, 0);
}

TEST(PlanValidator, LatticeMovesSweepEveryCellOnTheWay) {
  // A wall cell at x = 2: a move of 3 cells from x = 0 jumps over it in one step, and is still a
  // sweep through it; without the wall it is legal on a lattice of 3 (and of 4), not of 2.
  const GridMap wall = mapFromRows({"..@..."});
  const GridMap open = freeMap(6, 1);
  const std::vector<Robot> robots = {dot("a", {0, 0, 0}, {3, 0, 0})};
  const std::vector<Path> jump = {{{0, 0, 0}, {3, 0, 0}}};
  ActionModel lattice;
  lattice.step = 3;
  EXPECT_EQ(check(wall, robots, jump, lattice).kind, Kind::SweepInObstacle);
  EXPECT_EQ(check(open, robots, jump, lattice).kind, Kind::None);
  lattice.step = 4;
  EXPECT_EQ(check(open, robots, jump, lattice).kind, Kind::None);
  lattice.step = 2;
  EXPECT_EQ(check(open, robots, jump, lattice).kind, Kind::IllegalAction);
  // Two robots whose long moves pass through each other's way in one step.
  const std::vector<Robot> pair = {dot("a", {0, 0, 0}, {3, 0, 0}), dot("b", {4, 0, 1}, {1, 0, 1})};
  lattice.step = 3;
  EXPECT_EQ(check(open, pair, {{{0, 0, 0}, {3, 0, 0}}, {{4, 0, 1}, {1, 0, 1}}}, lattice).kind,
            Kind::TransferConflict);
}

TEST(PlanValidator, TurnsFromAStartYawSweepEveryCellOnTheWay) {
  // A stick 6 cells long at 45 degrees turns onto heading +x; the cell (13, 11) is touched only
  // while it turns (its front end passes over it), not at either end.
  std::vector<std::string> rows(20, std::string(20, '.'));
  rows[11][13] = '@';
  Robot stick = robot("stick", Footprint::block(-3.0, -0.2, 3.0, 0.2), {10, 10, 0}, {10, 10, 0});
  stick.start_yaw = 0.785398;
  const std::vector<Path> turn = {{{10, 10, 0}, {10, 10, 0}}};
  EXPECT_EQ(check(mapFromRows(rows), {stick}, turn).kind, Kind::SweepInObstacle);
  EXPECT_EQ(check(freeMap(20, 20), {stick}, turn).kind, Kind::None);
  // The turn is a step of its own: a path that moves at once is illegal.
  EXPECT_EQ(check(freeMap(20, 20), {stick}, {{{10, 10, 0}, {11, 10, 0}}}).kind, Kind::WrongTarget);
  Robot moving = stick;
  moving.target = {11, 10, 0};
  EXPECT_EQ(check(freeMap(20, 20), {moving}, {{{10, 10, 0}, {11, 10, 0}}}).kind, Kind::IllegalAction);
  // Another robot standing where only the turn passes meets it.
  const std::vector<Robot> pair = {stick, dot("d", {13, 11, 0}, {13, 11, 0})};
  EXPECT_EQ(check(freeMap(20, 20), pair, {turn[0], {{13, 11, 0}}}).kind, Kind::TransferConflict);
}

TEST(PlanValidator, VertexConflict) {
  const GridMap map = freeMap(5, 1);
  const auto v = check(map, {dot("a", {0, 0, 0}, {2, 0, 0}), dot("b", {4, 0, 1}, {3, 0, 1})},
                       {{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{4, 0, 1}, {3, 0, 1}, {2, 0, 1}, {3, 0, 1}}});
  EXPECT_EQ(v.kind, Kind::VertexConflict);
  EXPECT_EQ(v.time, 2);
  EXPECT_EQ(v.robot, 0);
  EXPECT_EQ(v.other, 1);
}

TEST(PlanValidator, SwapIsATransferConflict) {
  const GridMap map = freeMap(2, 1);
  const auto v = check(map, {dot("a", {0, 0, 0}, {1, 0, 0}), dot("b", {1, 0, 1}, {0, 0, 1})},
                       {{{0, 0, 0}, {1, 0, 0}}, {{1, 0, 1}, {0, 0, 1}}});
  EXPECT_EQ(v.kind, Kind::TransferConflict);
  EXPECT_EQ(v.time, 0);
}

TEST(PlanValidator, TurningIntoAWaitingRobotIsATransferConflict) {
  // The block's turn sweeps (3, 2), where a waits; no footprints overlap before or after.
  const GridMap map = freeMap(5, 5);
  const auto v = check(map, {robot("b", Footprint::block(-0.5, -0.5, 1.5, 0.5), {1, 2, 0}, {1, 2, 2}),
                             dot("a", {3, 2, 0}, {3, 2, 0})},
                       {{{1, 2, 0}, {1, 2, 2}}, {{3, 2, 0}}});
  EXPECT_EQ(v.kind, Kind::TransferConflict);
  EXPECT_EQ(v.robot, 0);
  EXPECT_EQ(v.other, 1);
}

TEST(PlanValidator, ArrivedRobotsStayAtTheirTargets) {
  // a arrives at (2, 0) at t = 2 and stays; b drives through (2, 0) at t = 4.
  const GridMap map = freeMap(5, 2);
  const auto v = check(map, {dot("a", {1, 1, 3}, {2, 0, 0}), dot("b", {0, 0, 0}, {4, 0, 0})},
                       {{{1, 1, 3}, {1, 0, 3}, {1, 0, 0}, {2, 0, 0}},
                        {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}}});
  EXPECT_EQ(v.kind, Kind::VertexConflict);
  EXPECT_EQ(v.time, 5);
}

TEST(PlanValidator, LargeFootprintsConflictAcrossCells) {
  // Two circles of radius 1 (3 x 3 cells) three cells apart are clear; two apart they overlap.
  const GridMap map = freeMap(8, 3);
  auto big = [](const std::string& id, GridPose s, GridPose t) { return robot(id, Footprint::circle(1.0), s, t); };
  EXPECT_EQ(check(map, {big("a", {1, 1, 0}, {1, 1, 0}), big("b", {4, 1, 1}, {4, 1, 1})}, {{{1, 1, 0}}, {{4, 1, 1}}}).kind,
            Kind::None);
  EXPECT_EQ(check(map, {big("a", {1, 1, 0}, {1, 1, 0}), big("b", {4, 1, 1}, {3, 1, 1})},
                  {{{1, 1, 0}}, {{4, 1, 1}, {3, 1, 1}}})
                .kind,
            Kind::VertexConflict);
}

// The first violation found with a broad phase (pairs whose boxes overlap) is the one a check of
// every pair at every step finds: same time, kind and robots, on random walks of mixed robots on
// a small map (most walks collide somewhere, some do not).
TEST(PlanValidatorDifferential, BroadPhaseFindsTheFirstConflictOfEveryPair) {
  const GridMap map = freeMap(10, 10);
  const std::vector<Footprint> kinds{Footprint::circle(0.4), Footprint::block(-0.5, -0.5, 1.5, 0.5),
                                     Footprint::circle(0.9)};
  Rng rng(21);
  int conflicts = 0, clean = 0;
  for (int round = 0; round < 300; ++round) {
    const int n = 2 + static_cast<int>(rng.uniformInt(0, 3));
    std::vector<Footprint> footprints;
    for (int i = 0; i < n; ++i) footprints.push_back(kinds[rng.uniformInt(0, 2)]);
    const FleetGraphs graphs(map, footprints);
    std::vector<Robot> robots;
    std::vector<Path> paths;
    for (int i = 0; i < n; ++i) {
      const StateGraph& g = graphs.graph(i);
      StateId s = kNoState;
      while (s == kNoState || !g.valid(s)) {
        s = g.id({static_cast<int>(rng.uniformInt(0, 9)), static_cast<int>(rng.uniformInt(0, 9)),
                  static_cast<int>(rng.uniformInt(0, 3))});
      }
      Path p{g.pose(s)};
      for (int t = 0, len = static_cast<int>(rng.uniformInt(0, 8)); t < len; ++t) {
        std::vector<StateId> next{s};
        g.forEachSuccessor(s, [&](Action, StateId x) { next.push_back(x); });
        s = next[rng.uniformInt(0, static_cast<std::int64_t>(next.size()) - 1)];
        p.push_back(g.pose(s));
      }
      robots.push_back(robot("r" + std::to_string(i), footprints[i], p.front(), p.back()));
      paths.push_back(p);
    }
    // Reference: every pair at every step, in the validator's order.
    std::vector<FootprintCells> cells;
    for (const Footprint& f : footprints) cells.emplace_back(f);
    int horizon = 0;
    for (const Path& p : paths) horizon = std::max(horizon, static_cast<int>(p.size()) - 1);
    auto at = [&](int i, int t) { return paths[i][std::min<std::size_t>(t, paths[i].size() - 1)]; };
    Violation expected;
    auto vertex = [&](int t) {
      for (int i = 0; i < n && expected.kind == Kind::None; ++i)
        for (int j = i + 1; j < n && expected.kind == Kind::None; ++j)
          if (footprintsOverlap(cells[i], at(i, t), cells[j], at(j, t)))
            expected = {Kind::VertexConflict, i, j, t};
    };
    vertex(0);
    for (int t = 0; t < horizon && expected.kind == Kind::None; ++t) {
      vertex(t + 1);
      for (int i = 0; i < n && expected.kind == Kind::None; ++i)
        for (int j = i + 1; j < n && expected.kind == Kind::None; ++j) {
          const Action ai = *actionBetween(at(i, t), at(i, t + 1), ActionModel{});
          const Action aj = *actionBetween(at(j, t), at(j, t + 1), ActionModel{});
          if (sweepsOverlap(cells[i], at(i, t), ai, cells[j], at(j, t), aj))
            expected = {Kind::TransferConflict, i, j, t};
        }
    }
    const Violation v = check(map, robots, paths);
    ASSERT_EQ(v.kind, expected.kind) << "round " << round << ": " << v.message;
    EXPECT_EQ(v.robot, expected.robot) << "round " << round;
    EXPECT_EQ(v.other, expected.other) << "round " << round;
    EXPECT_EQ(v.time, expected.time) << "round " << round;
    (v.kind == Kind::None ? clean : conflicts) += 1;
  }
  EXPECT_GT(conflicts, 50);
  EXPECT_GT(clean, 20);
}

}  // namespace
}  // namespace fleet_planner
