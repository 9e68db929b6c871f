// The execution monitor without a master: a plan of the service, executed by feeding the
// robots' poses as a robot's TF would give them.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <fleet_planner/RobotExecution.h>

#include "fleet_planner/execution/step_dependencies.h"
#include "fleet_planner/model/footprint_cells.h"
#include "fleet_planner/ros/conversions.h"
#include "fleet_planner/ros/execution_monitor.h"
#include "ros_test_util.h"

namespace fleet_planner::test {
namespace {

using RobotMsg = fleet_planner::RobotExecution;
using Poses = std::vector<std::optional<geometry_msgs::Pose2D>>;

class ExecutionMonitorTest : public ::testing::Test {
 protected:
  ExecutionMonitorTest() : service(PlannerConfig{}) {
    service.setMap(occupancyGrid(24, 12, kRes, kOx, kOy, {{8, 8}, {8, 9}, {15, 1}}));
    service.setFootprints(registry());
    call = service.plan(swapRequest(), nullptr);
  }
  void SetUp() override {
    ASSERT_EQ(call.response.status, fleet_planner::PlanFleet::Response::SUCCESS) << call.response.message;
    ASSERT_TRUE(call.executable);
  }
  ExecutionMonitor started(ExecutionSettings settings = {}) {
    ExecutionMonitor monitor(settings);
    monitor.start(*call.executable, 0.5, "map", ros::Time(100));
    return monitor;
  }
  const geometry_msgs::Pose2D& state(int robot, int k) const { return call.executable->poses[robot][k]; }
  Poses startPoses() const {
    Poses poses;
    for (std::size_t i = 0; i < call.executable->poses.size(); ++i) poses.push_back(state(i, 0));
    return poses;
  }
  /// Moves every robot but `held` to its released state and updates, until nothing changes.
  fleet_planner::FleetExecution driveAllBut(ExecutionMonitor& monitor, Poses& poses, int held, double& t) {
    fleet_planner::FleetExecution e = monitor.update(poses, ros::Time(t));
    for (int round = 0; round < 10000; ++round) {
      bool moved = false;
      for (std::size_t i = 0; i < poses.size(); ++i) {
        if (static_cast<int>(i) == held || e.robots[i].released == e.robots[i].progress) continue;
        poses[i] = monitor.plan().poses[i][e.robots[i].released];  // the plan as revised
        moved = true;
      }
      t += 0.1;
      e = monitor.update(poses, ros::Time(t));
      if (!moved) break;
    }
    return e;
  }

  FleetPlanningService service;
  PlanCall call;
};

TEST_F(ExecutionMonitorTest, ReleasesFollowProgressAndEveryRobotArrives) {
  ExecutionMonitor monitor = started();
  Poses poses = startPoses();
  const auto first = monitor.update(poses, ros::Time(100));
  EXPECT_GT(first.dependencies, 0u) << "the swap makes robots wait for each other";
  bool someone_held = false;
  for (const auto& r : first.robots) someone_held |= r.released < r.last_state;
  EXPECT_TRUE(someone_held);
  double t = 100;
  const auto end = driveAllBut(monitor, poses, -1, t);
  EXPECT_TRUE(end.done);
  EXPECT_EQ(end.collisions, 0u);
  for (const auto& r : end.robots) {
    EXPECT_EQ(r.state, RobotMsg::ARRIVED) << r.robot_id;
    EXPECT_EQ(r.progress, r.last_state) << r.robot_id;
  }
}

// A robot counts as at a state within the tolerances of it, so it may still cover a cell of a
// step another robot was to take once it had left. On the hall at 0.05 m (a lattice of several
// cells), the first such case of the swap: robot `o` halts short of its state `s`, where it
// counts as arrived, with its footprint on a cell of robot i's step t (which waits for o at s).
// Nobody is released into that step while o stands there; once o is at s, everybody arrives,
// with no overlap at any update.
TEST(ExecutionMonitorLag, NobodyIsReleasedOntoARobotThatCountsAsGoneButIsNotQuite) {
  constexpr double kFine = 0.05;
  std::vector<std::pair<int, int>> blocked;  // the hall's blocked cells, 5 x 5 cells each
  for (const auto& [x, y] : std::vector<std::pair<int, int>>{{8, 8}, {8, 9}, {15, 1}}) {
    for (int k = 0; k < 25; ++k) blocked.push_back({5 * x + k % 5, 5 * y + k / 5});
  }
  PlannerConfig config;
  config.cell_steps = false;  // states a lattice step apart, the tolerance in proportion
  FleetPlanningService service{config};
  service.setMap(occupancyGrid(120, 60, kFine, kOx, kOy, blocked));
  service.setFootprints(registry());
  const PlanCall call = service.plan(swapRequest(), nullptr);
  ASSERT_TRUE(call.executable) << call.response.message;
  const ExecutablePlan& plan = *call.executable;
  ASSERT_GT(plan.lattice_step, 1);
  ExecutionSettings settings;
  settings.position_tolerance = 0.45 * plan.lattice_step * kFine;
  settings.heading_tolerance = 0.3;

  // Where o stands short of state s: a fraction f of the step there left, within the tolerances.
  auto shortOf = [&](int o, int s, double f) {
    const auto &a = plan.poses[o][s - 1], &b = plan.poses[o][s];
    geometry_msgs::Pose2D p = b;
    p.x -= f * (b.x - a.x), p.y -= f * (b.y - a.y), p.theta -= f * wrapAngle(b.theta - a.theta);
    return p;
  };
  auto coversStep = [&](int o, const geometry_msgs::Pose2D& p, const PlanCells& cells, int i, int t) {
    const double gx = (p.x - kOx) / kFine, gy = (p.y - kOy) / kFine;
    const Cell cell{static_cast<int>(std::floor(gx)), static_cast<int>(std::floor(gy))};
    const CellSet at = footprintCellsAt(plan.instance.robots[o].footprint, p.theta,
                                        Eigen::Vector2d(gx - cell.x - 0.5, gy - cell.y - 0.5));
    return overlap(cells.during(i, t), {&at, cell});
  };
  ActionModel model;
  model.step = plan.lattice_step;
  model.allow_backward = plan.allow_backward;
  const PlanCells cells(plan.instance, plan.plan, model);
  const StepDependencies deps = buildStepDependencies(cells);
  int i = -1, t = -1, o = -1, s = -1;
  geometry_msgs::Pose2D halted;
  for (int a = 0; a < cells.robots() && i < 0; ++a) {
    for (int step = 0; step < static_cast<int>(deps.before[a].size()) && i < 0; ++step) {
      for (const Requirement& r : deps.before[a][step]) {
        const auto &from = plan.poses[r.robot][r.state - 1], &to = plan.poses[r.robot][r.state];
        const double len = std::hypot(to.x - from.x, to.y - from.y), turn = std::abs(wrapAngle(to.theta - from.theta));
        const double f = std::min(len > 0 ? 0.9 * settings.position_tolerance / len : 1.0,
                                  turn > 0 ? 0.9 * settings.heading_tolerance / turn : 1.0);
        if (f >= 1.0 || !coversStep(r.robot, shortOf(r.robot, r.state, f), cells, a, step)) continue;
        i = a, t = step, o = r.robot, s = r.state, halted = shortOf(o, s, f);
        break;
      }
    }
  }
  ASSERT_GE(i, 0) << "no robot of the swap covers a step of another short of a state it waits for";

  ExecutionMonitor monitor(settings);
  monitor.start(plan, 0.5, "map", ros::Time(100));
  Poses poses;
  for (const auto& path : plan.poses) poses.push_back(path[0]);
  double time = 100;
  fleet_planner::FleetExecution e = monitor.update(poses, ros::Time(time));
  std::uint32_t most_released = 0;  // robot i's, while o halts
  for (int round = 0; round < 10000; ++round) {
    bool moved = false;
    for (int r = 0; r < static_cast<int>(poses.size()); ++r) {
      const geometry_msgs::Pose2D p =
          r == o && static_cast<int>(e.robots[r].released) >= s ? halted : plan.poses[r][e.robots[r].released];
      moved |= p.x != poses[r]->x || p.y != poses[r]->y || p.theta != poses[r]->theta;
      poses[r] = p;
    }
    time += 0.1;
    e = monitor.update(poses, ros::Time(time));
    most_released = std::max(most_released, e.robots[i].released);
    if (!moved) break;
  }
  EXPECT_EQ(e.robots[o].progress, static_cast<unsigned>(s)) << "o counts as at s";
  EXPECT_LE(most_released, static_cast<unsigned>(t)) << "released into the cells o stands on";
  EXPECT_EQ(e.collisions, 0u);
  poses[o] = plan.poses[o][s];
  for (int round = 0; round < 10000 && !e.done; ++round) {
    for (int r = 0; r < static_cast<int>(poses.size()); ++r) poses[r] = plan.poses[r][e.robots[r].released];
    time += 0.1;
    e = monitor.update(poses, ros::Time(time));
  }
  EXPECT_TRUE(e.done);
  EXPECT_EQ(e.collisions, 0u);
}

TEST_F(ExecutionMonitorTest, AHeldRobotHoldsThoseThatWaitForItAndOnlyUntilItMoves) {
  bool someone_waited = false;
  for (int held = 0; held < 3; ++held) {
    ExecutionMonitor monitor = started();
    Poses poses = startPoses();
    double t = 100;
    const auto stuck = driveAllBut(monitor, poses, held, t);
    EXPECT_FALSE(stuck.done);
    for (int i = 0; i < 3; ++i) {
      const auto& r = stuck.robots[i];
      if (i == held || r.state == RobotMsg::ARRIVED) continue;
      EXPECT_EQ(r.state, RobotMsg::WAITING) << r.robot_id;
      EXPECT_FALSE(r.blocked_by.empty()) << r.robot_id;
      someone_waited |= r.blocked_by == stuck.robots[held].robot_id;
    }
    const auto end = driveAllBut(monitor, poses, -1, t);
    EXPECT_TRUE(end.done) << "held " << held;
    EXPECT_EQ(end.collisions, 0u);
  }
  EXPECT_TRUE(someone_waited) << "some robot waits for a held one";
}

TEST_F(ExecutionMonitorTest, ARobotSeenBetweenTwoStatesHasReachedTheFirst) {
  ExecutionMonitor monitor = started();
  Poses poses = startPoses();
  const auto e = monitor.update(poses, ros::Time(100));
  for (int i = 0; i < 3; ++i) {
    // The first move of the robot's release beyond state 1: sampled halfway.
    for (int k = 1; k + 1 <= static_cast<int>(e.robots[i].released); ++k) {
      const auto &a = state(i, k), &b = state(i, k + 1);
      if (a.x == b.x && a.y == b.y) continue;
      geometry_msgs::Pose2D mid = a;
      mid.x = (a.x + b.x) / 2, mid.y = (a.y + b.y) / 2;
      poses[i] = mid;
      EXPECT_EQ(monitor.update(poses, ros::Time(101)).robots[i].progress, static_cast<unsigned>(k));
      return;
    }
  }
  FAIL() << "no robot released beyond its first move";
}

TEST_F(ExecutionMonitorTest, OverlapsAreCountedOncePerContact) {
  ExecutionMonitor monitor = started();
  Poses poses = startPoses();
  EXPECT_EQ(monitor.update(poses, ros::Time(100)).collisions, 0u);
  Poses touching = poses;
  touching[1] = poses[0];  // amr_2 where amr_1 stands
  EXPECT_EQ(monitor.update(touching, ros::Time(101)).collisions, 1u);
  EXPECT_EQ(monitor.update(touching, ros::Time(102)).collisions, 1u);
  EXPECT_EQ(monitor.update(poses, ros::Time(103)).collisions, 1u);
  Poses near = poses;  // close, not touching: the two discs (radii 0.3 and 0.2 m) more than 2 cells apart
  near[1] = poses[0];
  near[1]->y += 0.5 + 2.5 * kRes;
  EXPECT_EQ(monitor.update(near, ros::Time(104)).collisions, 1u);
  const auto again = monitor.update(touching, ros::Time(105));
  EXPECT_EQ(again.collisions, 2u);
  const auto diagnostics = executionDiagnostics(again, {}, ros::Time(105));
  ASSERT_EQ(diagnostics.status.size(), 4u);
  EXPECT_EQ(diagnostics.status[0].level, diagnostic_msgs::DiagnosticStatus::ERROR);
}

TEST_F(ExecutionMonitorTest, ARobotAwayFromItsPathIsOffItsPath) {
  ExecutionMonitor monitor = started();
  Poses poses = startPoses();
  EXPECT_NE(monitor.update(poses, ros::Time(100)).robots[2].state, RobotMsg::OFF_PATH);
  poses[2]->y += 0.15;  // within the tolerance (0.3 m), at no state
  EXPECT_NE(monitor.update(poses, ros::Time(101)).robots[2].state, RobotMsg::OFF_PATH);
  // Away from every state of its path: then no state of its release matches either.
  const ProgressMatcher whole(call.executable->poses[2], 0.05, 0.2);
  const int last = whole.lastState();
  for (double dy : {0.5, -0.5, 1.0, -1.0, 1.5, -1.5}) {
    geometry_msgs::Pose2D away = *poses[2];
    away.y += dy - 0.15;
    if (whole.distanceToPath(away, 0, last) > 0.4) {
      poses[2] = away;
      break;
    }
  }
  ASSERT_GT(whole.distanceToPath(*poses[2], 0, last), 0.4);
  const auto e = monitor.update(poses, ros::Time(102));
  EXPECT_EQ(e.robots[2].state, RobotMsg::OFF_PATH);
  EXPECT_EQ(executionDiagnostics(e, {}, ros::Time(102)).status[3].level, diagnostic_msgs::DiagnosticStatus::ERROR);
}

// The tug is pushed off its path onto amr_1's way (at the first state from two thirds along it
// where it touches nobody as they stand at their starts): amr_1 is released no further than
// the step before the place where the tug stands, whatever the dependencies allow, and goes on
// once the tug is back.
TEST_F(ExecutionMonitorTest, NobodyIsReleasedOntoWhereARobotOffItsPathStands) {
  const auto& way = call.executable->poses[0];
  int k = -1;
  for (int j = static_cast<int>(way.size()) * 2 / 3; j < static_cast<int>(way.size()) && k < 0; ++j) {
    ExecutionMonitor probe = started();
    Poses at = startPoses();
    at[2] = way[j];
    const auto e = probe.update(at, ros::Time(100));
    if (e.collisions == 0 && e.robots[2].state == RobotMsg::OFF_PATH) k = j;
  }
  ASSERT_GE(k, 0) << "no free place on amr_1's way";
  ExecutionMonitor monitor = started();
  Poses poses = startPoses();
  monitor.update(poses, ros::Time(100));
  poses[2] = way[k];
  double t = 100;
  auto e = driveAllBut(monitor, poses, 2, t);
  EXPECT_EQ(e.robots[2].state, RobotMsg::OFF_PATH);
  EXPECT_EQ(e.collisions, 0u);
  EXPECT_LT(e.robots[0].released, k);
  EXPECT_EQ(e.robots[0].blocked_by, "tug");
  poses[2] = startPoses()[2];  // back where it was
  e = driveAllBut(monitor, poses, -1, t);
  EXPECT_TRUE(e.done);
  EXPECT_EQ(e.collisions, 0u);
}

// Pushed 0.5 m off its path, a robot is planned again from where it stands: its timeline
// begins there and ends at its goal, and everybody arrives. The others keep their plans, which
// in this small hall may leave a pushed robot no way home (their released steps and parked
// targets close it): the first robot and side (the tug first) off its path, onto nobody, from
// which the replan finds a way is taken, and some must.
TEST_F(ExecutionMonitorTest, ARobotOffItsPathIsPlannedAgainFromWhereItStands) {
  std::optional<ExecutionMonitor> monitor;
  Poses poses;
  ReplanReport report;
  std::string tried;
  int pushed = -1;
  for (const int robot : {2, 1, 0}) {
    for (const auto& [dx, dy] : std::vector<std::pair<double, double>>{{0.5, 0}, {-0.5, 0}, {0, 0.5}, {0, -0.5}}) {
      monitor.emplace(started());
      poses = startPoses();
      monitor->update(poses, ros::Time(100));
      poses[robot]->x += dx;
      poses[robot]->y += dy;
      const auto e = monitor->update(poses, ros::Time(100.1));
      // Pushed along its own path, or onto another robot: not this test's case.
      if (e.robots[robot].state != RobotMsg::OFF_PATH || e.collisions > 0) continue;
      EXPECT_EQ(monitor->offPathRobots(), std::vector<int>{robot});
      report = monitor->replan({robot}, 1.0, PoseTolerance{});
      if (report.merged) {
        pushed = robot;
        break;
      }
      tried += report.message + "; ";
    }
    if (pushed >= 0) break;
  }
  ASSERT_GE(pushed, 0) << tried;
  const geometry_msgs::Pose2D goal = call.executable->poses[pushed].back();
  EXPECT_NE(report.message.find("off its path"), std::string::npos) << report.message;
  const auto& timeline = monitor->plan().poses[pushed];
  EXPECT_LE(std::hypot(timeline.front().x - poses[pushed]->x, timeline.front().y - poses[pushed]->y), kRes);
  EXPECT_DOUBLE_EQ(timeline.back().x, goal.x);
  EXPECT_DOUBLE_EQ(timeline.back().y, goal.y);
  EXPECT_NE(monitor->update(poses, ros::Time(100.2)).robots[pushed].state, RobotMsg::OFF_PATH);
  double t = 100.2;
  const auto e = driveAllBut(*monitor, poses, -1, t);
  EXPECT_TRUE(e.done);
  EXPECT_EQ(e.collisions, 0u);
}

TEST_F(ExecutionMonitorTest, MissingPosesAndLongWaitsAreReported) {
  ExecutionSettings settings;
  settings.blocked_timeout = 1.0;
  for (int held = 0; held < 3; ++held) {
    ExecutionMonitor monitor = started(settings);
    Poses poses = startPoses();
    double t = 100;
    auto e = driveAllBut(monitor, poses, held, t);
    poses[held].reset();
    e = monitor.update(poses, ros::Time(t + 60.0));  // later than any state's planned time
    EXPECT_EQ(e.robots[held].state, RobotMsg::NO_POSE);
    for (int i = 0; i < 3; ++i) {
      if (i == held || e.robots[i].state == RobotMsg::ARRIVED) continue;
      EXPECT_EQ(e.robots[i].state, RobotMsg::BLOCKED) << e.robots[i].robot_id;
      EXPECT_GT(e.robots[i].lateness, 0.0);
    }
    const auto diagnostics = executionDiagnostics(e, settings, ros::Time(t + 60.0));
    EXPECT_EQ(diagnostics.status[1 + held].level, diagnostic_msgs::DiagnosticStatus::ERROR);
  }
}

}  // namespace
}  // namespace fleet_planner::test

namespace fleet_planner::test {
namespace {

// A path that comes back to a pose: turn to +y, turn back, then move. Standing at the start,
// the robot matches state 2 as well as state 0: its progress must stay 0, or the robots that
// wait for it would be let into cells it has not left.
TEST(ExecutionMonitorProgress, APoseTheRobotComesBackToIsNotTakenForTheLaterState) {
  ExecutablePlan plan;
  const auto grid = occupancyGrid(10, 10, 0.5, 0.0, 0.0);
  plan.map = std::make_shared<GridMap>(convert(grid, OccupancyPolicy{}));
  Robot robot;
  robot.id = "tug";
  robot.footprint = Footprint::block(-0.6, -0.4, 0.6, 0.4);
  robot.start = {3, 3, 0};
  robot.target = {4, 3, 0};
  plan.instance.robots = {robot};
  plan.plan.paths = {{{3, 3, 0}, {3, 3, 2}, {3, 3, 0}, {4, 3, 0}}};
  plan.poses.emplace_back();
  for (const GridPose& s : plan.plan.paths[0]) plan.poses[0].push_back(toPose2D(*plan.map, s));
  ExecutionMonitor monitor(ExecutionSettings{});
  monitor.start(plan, 0.5, "map", ros::Time(100));
  Poses poses = {plan.poses[0][0]};
  EXPECT_EQ(monitor.update(poses, ros::Time(100)).robots[0].progress, 0u);
  poses[0]->theta = 0.8;  // turning to +y: on the way from state 0 to 1
  EXPECT_EQ(monitor.update(poses, ros::Time(101)).robots[0].progress, 0u);
  poses[0] = plan.poses[0][1];
  EXPECT_EQ(monitor.update(poses, ros::Time(102)).robots[0].progress, 1u);
  poses[0] = plan.poses[0][2];
  EXPECT_EQ(monitor.update(poses, ros::Time(103)).robots[0].progress, 2u);
  poses[0]->x += 0.25;  // halfway to state 3
  EXPECT_EQ(monitor.update(poses, ros::Time(104)).robots[0].progress, 2u);
  poses[0] = plan.poses[0][3];
  const auto end = monitor.update(poses, ros::Time(105));
  EXPECT_EQ(end.robots[0].progress, 3u);
  EXPECT_TRUE(end.done);
}

}  // namespace
}  // namespace fleet_planner::test
