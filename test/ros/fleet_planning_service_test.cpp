// The PlanFleet service logic without a master: every plan it returns passes the independent
// validator, and every kind of bad request gets its own status and a message that names the
// robot and the problem.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <future>
#include <limits>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/ros/conversions.h"
#include "fleet_planner/ros/fleet_planning_service.h"
#include "ros_test_util.h"

namespace fleet_planner::test {
namespace {

using Request = fleet_planner::PlanFleet::Request;
using Response = fleet_planner::PlanFleet::Response;
using RobotResultMsg = fleet_planner::RobotResult;

constexpr double kPi = 3.14159265358979323846;

class PlanningServiceTest : public ::testing::Test {
 protected:
  PlanningServiceTest() : service(PlannerConfig{}) {
    service.setMap(occupancyGrid(24, 12, kRes, kOx, kOy, {{8, 8}, {8, 9}, {15, 1}}));
    service.setFootprints(registry());
  }
  PlanCall plan(const Request& request) { return service.plan(request, nullptr); }

  /// The response is a success whose timelines pass the validator and match the request.
  void expectValidPlan(const Request& request, const Response& response) {
    ASSERT_EQ(response.status, Response::SUCCESS) << response.message;
    ASSERT_EQ(response.timelines.size(), request.tasks.size());
    const GridMap map = convert(occupancyGrid(24, 12, kRes, kOx, kOy, {{8, 8}, {8, 9}, {15, 1}}), OccupancyPolicy{});
    const Instance instance = instanceOf(request, registry(), response, kRes);
    ActionModel model;
    model.allow_backward = response.statistics.backward_moves;  // the node's default: allowed
    model.step = static_cast<int>(response.statistics.lattice_step);
    const auto validation = validatePlan(map, instance, planOf(response), model);
    EXPECT_TRUE(validation.valid()) << validation.violation.message;
    for (std::size_t i = 0; i < request.tasks.size(); ++i) {
      const auto& states = response.timelines[i].states;
      EXPECT_EQ(response.timelines[i].robot_id, request.tasks[i].robot_id);
      EXPECT_NEAR(states.front().x, request.tasks[i].start.x, 1e-6);
      EXPECT_NEAR(states.front().y, request.tasks[i].start.y, 1e-6);
      EXPECT_NEAR(states.back().x, request.tasks[i].goal.x, 1e-6);
      EXPECT_NEAR(states.back().y, request.tasks[i].goal.y, 1e-6);
      EXPECT_NEAR(std::abs(wrapAngle(states.back().yaw - request.tasks[i].goal.theta)), 0.0, 1e-6);
      EXPECT_EQ(response.robots[i].status, RobotResultMsg::OK) << response.robots[i].message;
      for (std::size_t t = 0; t < states.size(); ++t) {
        EXPECT_NEAR(states[t].time, t * PlannerConfig{}.seconds_per_step, 1e-9);
      }
    }
  }

  FleetPlanningService service;
};

TEST_F(PlanningServiceTest, PlansAValidFleetPlanWithEachBackendAndMode) {
  // Raw LA-CBS proves its optimum here in about 320 constraint-tree nodes (one robot must wait
  // about ten steps for another; la_cbs_scenarios_test pins that case).
  const std::vector<std::pair<const char*, std::uint8_t>> cases = {{"la_cbs", Request::DECOMPOSITION_LAYERED},
                                                                   {"la_cbs", Request::DECOMPOSITION_RAW},
                                                                   {"la_lacam", Request::DECOMPOSITION_LAYERED},
                                                                   {"la_lacam", Request::DECOMPOSITION_RAW}};
  for (const auto& [backend, mode] : cases) {
    {
      SCOPED_TRACE(std::string(backend) + (mode == Request::DECOMPOSITION_RAW ? " raw" : " layered"));
      Request request = swapRequest();
      request.backend = backend;
      request.decomposition = mode;
      const PlanCall call = plan(request);
      expectValidPlan(request, call.response);
      const auto& stats = call.response.statistics;
      EXPECT_EQ(stats.robots, 3u);
      EXPECT_GT(stats.soc, 0);
      EXPECT_GT(stats.makespan, 0);
      EXPECT_GE(stats.largest_subproblem, 1u);
      if (mode == Request::DECOMPOSITION_RAW) {
        EXPECT_EQ(call.response.subproblems.size(), 1u);
      }
      std::size_t robots_in_subproblems = 0;
      for (const auto& s : call.response.subproblems) {
        robots_in_subproblems += s.robot_ids.size();
        // LA-CBS proves a lower bound on each subproblem's cost (its optimum here), LA-LaCAM none.
        if (std::string(backend) == "la_cbs") {
          EXPECT_GE(s.lower_bound, 0);
        } else {
          EXPECT_EQ(s.lower_bound, -1);
        }
      }
      EXPECT_EQ(robots_in_subproblems, 3u);
      EXPECT_EQ(call.placements.size(), 3u);
    }
  }
}

TEST_F(PlanningServiceTest, SameRequestAndSeedGiveTheSamePlanAndReuseTheGraphs) {
  Request request = swapRequest();
  request.seed = 42;
  const Response first = plan(request).response;
  const Response second = plan(request).response;
  ASSERT_EQ(first.status, Response::SUCCESS) << first.message;
  EXPECT_EQ(planOf(first).paths, planOf(second).paths);
  EXPECT_EQ(second.statistics.precompute_time, 0.0);  // graphs cached: same map, same footprints
}

TEST_F(PlanningServiceTest, DefaultTimeLimitIsMinusOne) {
  Request request = swapRequest();
  request.time_limit = -1;
  expectValidPlan(request, plan(request).response);
}

TEST(PlanningServiceNoMap, AnswersNoMap) {
  FleetPlanningService service{PlannerConfig{}};
  service.setFootprints(registry());
  const Response r = service.plan(swapRequest(), nullptr).response;
  EXPECT_EQ(r.status, Response::NO_MAP);
  EXPECT_NE(r.message.find("no map"), std::string::npos) << r.message;
}

TEST_F(PlanningServiceTest, UnknownRobotIsNamed) {
  Request request = swapRequest();
  request.tasks[1].robot_id = "ghost";
  const Response r = plan(request).response;
  EXPECT_EQ(r.status, Response::UNKNOWN_ROBOT);
  EXPECT_NE(r.message.find("'ghost'"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("amr_1"), std::string::npos) << "lists the known robots: " << r.message;
  EXPECT_EQ(r.robots[1].status, RobotResultMsg::UNKNOWN_ROBOT);
  EXPECT_EQ(r.robots[0].status, RobotResultMsg::NOT_PLANNED);
  EXPECT_TRUE(r.timelines.empty());
}

TEST_F(PlanningServiceTest, StartInAnObstacleNamesTheCell) {
  Request request = swapRequest();
  request.tasks[0].start.x = cx(8);
  request.tasks[0].start.y = cy(8);
  const Response r = plan(request).response;
  EXPECT_EQ(r.status, Response::INVALID_START);
  EXPECT_EQ(r.robots[0].status, RobotResultMsg::INVALID_START);
  EXPECT_NE(r.message.find("'amr_1'"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("blocked cell"), std::string::npos) << r.message;
}

TEST_F(PlanningServiceTest, GoalOffTheMap) {
  Request request = swapRequest();
  request.tasks[2].goal.x = 40.0;
  const Response r = plan(request).response;
  EXPECT_EQ(r.status, Response::INVALID_GOAL);
  EXPECT_EQ(r.robots[2].status, RobotResultMsg::INVALID_GOAL);
  EXPECT_NE(r.message.find("'tug'"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("off the map"), std::string::npos) << r.message;
}

TEST_F(PlanningServiceTest, NanPoseIsAnInvalidStart) {
  Request request = swapRequest();
  request.tasks[1].start.y = std::numeric_limits<double>::quiet_NaN();
  const Response r = plan(request).response;
  EXPECT_EQ(r.status, Response::INVALID_START);
  EXPECT_NE(r.message.find("y is nan"), std::string::npos) << r.message;
}

TEST_F(PlanningServiceTest, ZeroTimeLimitIsAnInvalidRequest) {
  Request request = swapRequest();
  request.time_limit = 0.0;
  const Response r = plan(request).response;
  EXPECT_EQ(r.status, Response::INVALID_REQUEST);
  EXPECT_NE(r.message.find("time_limit"), std::string::npos) << r.message;
}

TEST_F(PlanningServiceTest, UnknownBackendListsTheKnownOnes) {
  Request request = swapRequest();
  request.backend = "a_star_magic";
  const Response r = plan(request).response;
  EXPECT_EQ(r.status, Response::UNKNOWN_BACKEND);
  EXPECT_NE(r.message.find("a_star_magic"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("la_lacam"), std::string::npos) << r.message;
}

TEST_F(PlanningServiceTest, UnknownFallbackBackendNamesTheParameter) {
  PlannerConfig config;
  config.fallback = "teleport";
  // The node stops at startup on this (checkPlannerBackends); a service built anyway answers
  // INTERNAL_ERROR: the fault is the node's configuration, not the request.
  FleetPlanningService misconfigured(config);
  misconfigured.setMap(occupancyGrid(24, 12, kRes, kOx, kOy, {{8, 8}, {8, 9}, {15, 1}}));
  misconfigured.setFootprints(registry());
  const Response r = misconfigured.plan(swapRequest(), nullptr).response;
  EXPECT_EQ(r.status, Response::INTERNAL_ERROR);
  EXPECT_NE(r.message.find("'fallback'"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("teleport"), std::string::npos) << r.message;
}

TEST_F(PlanningServiceTest, BadRequestFieldsAreNamed) {
  Request request = swapRequest();
  request.steps = 7;
  EXPECT_NE(plan(request).response.message.find("steps"), std::string::npos);
  request = swapRequest();
  request.decomposition = 9;
  EXPECT_NE(plan(request).response.message.find("decomposition"), std::string::npos);
  request = swapRequest();
  request.tasks[2].robot_id = "amr_1";
  const Response r = plan(request).response;
  EXPECT_EQ(r.status, Response::INVALID_REQUEST);
  EXPECT_NE(r.message.find("two tasks"), std::string::npos) << r.message;
  request.tasks.clear();
  EXPECT_EQ(plan(request).response.status, Response::INVALID_REQUEST);
}

TEST_F(PlanningServiceTest, PosesOutsideTheTolerancesAreRejected) {
  Request request = swapRequest();
  request.tasks[0].start.x += 0.11;  // position_tolerance 0.1 m
  Response r = plan(request).response;
  EXPECT_EQ(r.status, Response::INVALID_START);
  EXPECT_NE(r.message.find("position_tolerance"), std::string::npos) << r.message;

  // Any yaw is a goal (and a start): the plan turns the robot in place to it.
  request = swapRequest();
  request.tasks[0].goal.theta = 0.5;  // beyond heading_tolerance (0.2 rad)
  request.tasks[1].start.theta += 2.0;
  r = plan(request).response;
  ASSERT_EQ(r.status, Response::SUCCESS) << r.message;
  EXPECT_NEAR(r.timelines[0].states.back().yaw, 0.5, 1e-9);
  EXPECT_NEAR(std::remainder(r.timelines[1].states.front().yaw - request.tasks[1].start.theta, 2 * kPi), 0.0, 1e-9);

  request = swapRequest();
  request.tasks[0].start.x += 0.05;  // within the tolerances: snapped to the cell centre
  request.tasks[0].start.theta = 2 * kPi + 0.1;
  const Response ok = plan(request).response;
  ASSERT_EQ(ok.status, Response::SUCCESS) << ok.message;
  EXPECT_NEAR(ok.timelines[0].states.front().x, cx(3), 1e-9);
}

TEST_F(PlanningServiceTest, OverlappingStartsAreAConflict) {
  Request request = swapRequest();
  request.tasks[1].start.x = cx(5);
  request.tasks[1].start.y = cy(3);
  const Response r = plan(request).response;
  EXPECT_EQ(r.status, Response::INVALID_START);
  EXPECT_EQ(r.robots[0].status, RobotResultMsg::CONFLICT);
  EXPECT_NE(r.message.find("overlaps"), std::string::npos) << r.message;
}

TEST_F(PlanningServiceTest, UnreachableGoalIsInfeasible) {
  // A wall across the map at x = 16: amr_1 cannot reach its goal.
  std::vector<std::pair<int, int>> wall;
  for (int y = 1; y < 11; ++y) wall.push_back({16, y});
  service.setMap(occupancyGrid(24, 12, kRes, kOx, kOy, wall));
  Request request = swapRequest();
  request.tasks.resize(1);
  const Response r = plan(request).response;
  EXPECT_EQ(r.status, Response::INFEASIBLE);
  EXPECT_EQ(r.robots[0].status, RobotResultMsg::UNREACHABLE);
  EXPECT_NE(r.message.find("not reachable"), std::string::npos) << r.message;
}

TEST_F(PlanningServiceTest, StartsFromTheLookupOrNoTransform) {
  Request request = swapRequest();
  request.tasks[0].start_from_tf = true;
  request.tasks[0].start = geometry_msgs::Pose2D();  // ignored
  const auto lookup = [](const std::string& id, geometry_msgs::Pose2D& pose, std::string& error) {
    if (id != "amr_1") return error = "unexpected robot", false;
    pose.x = cx(3), pose.y = cy(3), pose.theta = 0.0;
    return true;
  };
  const Response ok = service.plan(request, lookup).response;
  expectValidPlan(swapRequest(), ok);

  const auto broken = [](const std::string&, geometry_msgs::Pose2D&, std::string& error) {
    error = "frame amr_1/base_link does not exist";
    return false;
  };
  const Response r = service.plan(request, broken).response;
  EXPECT_EQ(r.status, Response::NO_TRANSFORM);
  EXPECT_NE(r.message.find("amr_1/base_link"), std::string::npos) << r.message;
}

TEST_F(PlanningServiceTest, AFootprintUpdateIsUsedByTheNextPlan) {
  auto fleet = registry();
  fleet.robots[0].radius = 1.0;  // amr_1 no longer fits between the wall and its start
  service.setFootprints(fleet);
  const Response r = plan(swapRequest()).response;
  EXPECT_EQ(r.status, Response::INVALID_START);
  EXPECT_EQ(r.robots[0].status, RobotResultMsg::INVALID_START);
  EXPECT_NE(r.message.find("'amr_1'"), std::string::npos) << r.message;
}

TEST_F(PlanningServiceTest, AMapUpdateDuringPlanningDoesNotTouchTheRunningCall) {
  const Request request = swapRequest();
  auto running = std::async(std::launch::async, [&] { return plan(request); });
  std::vector<std::pair<int, int>> wall;
  for (int y = 1; y < 11; ++y) wall.push_back({16, y});
  service.setMap(occupancyGrid(24, 12, kRes, kOx, kOy, wall));
  const PlanCall call = running.get();
  // Planned on one map or the other, never a mix: the old one gives a valid plan, the new one
  // (wall across the map) an INFEASIBLE answer.
  if (call.response.status == Response::SUCCESS) {
    expectValidPlan(request, call.response);
  } else {
    EXPECT_EQ(call.response.status, Response::INFEASIBLE) << call.response.message;
  }
  EXPECT_EQ(plan(request).response.status, Response::INFEASIBLE);  // the next call sees the new map
}

TEST(PlanningServiceMap, RejectsABrokenGridAndKeepsThePreviousOne) {
  FleetPlanningService service{PlannerConfig{}};
  service.setFootprints(registry());
  auto grid = occupancyGrid(24, 12, kRes, kOx, kOy);
  service.setMap(grid);
  grid.data.pop_back();
  EXPECT_THROW(service.setMap(grid), InputError);
  EXPECT_EQ(service.plan(swapRequest(), nullptr).response.status, Response::SUCCESS);
}

// --- Hostile requests: each gets its own status and a message naming the robot or the field. ---

TEST_F(PlanningServiceTest, EveryNonFinitePoseValueIsNamedPerRobotAndField) {
  const double bad_values[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity()};
  for (const bool goal : {false, true}) {
    for (const char* field : {"x", "y", "theta"}) {
      for (const double v : bad_values) {
        Request request = swapRequest();
        auto& pose = goal ? request.tasks[1].goal : request.tasks[1].start;
        (field[0] == 'x' ? pose.x : field[0] == 'y' ? pose.y : pose.theta) = v;
        const std::string what = std::string(goal ? "goal " : "start ") + field + " is ";
        SCOPED_TRACE(what + std::to_string(v));
        const Response r = plan(request).response;
        EXPECT_EQ(r.status, goal ? Response::INVALID_GOAL : Response::INVALID_START) << r.message;
        EXPECT_NE(r.message.find("robot 'amr_2': " + what), std::string::npos) << r.message;
        ASSERT_EQ(r.robots.size(), 3u);
        EXPECT_EQ(r.robots[1].status, goal ? RobotResultMsg::INVALID_GOAL : RobotResultMsg::INVALID_START);
        EXPECT_EQ(r.robots[0].status, RobotResultMsg::NOT_PLANNED);
        // The same answer without the map: checkRequest() needs neither map nor registry.
        const auto early = service.checkRequest(request);
        ASSERT_TRUE(early.has_value());
        EXPECT_EQ(early->status, r.status);
        EXPECT_EQ(early->message, r.message);
      }
    }
  }
}

TEST_F(PlanningServiceTest, AYawTooLargeToBeAnAngleIsRejected) {
  Request request = swapRequest();
  request.tasks[0].goal.theta = 1e20;  // matches some grid heading by chance: not a usable angle
  const Response r = plan(request).response;
  EXPECT_EQ(r.status, Response::INVALID_GOAL);
  EXPECT_NE(r.message.find("robot 'amr_1': goal theta 1e+20 rad is not an angle"), std::string::npos) << r.message;
  request = swapRequest();
  request.tasks[0].start.theta = 4 * kPi;  // a wrapped-around yaw is fine
  EXPECT_EQ(plan(request).response.status, Response::SUCCESS);
}

TEST_F(PlanningServiceTest, PosesFarOffTheMapAreNamedWithReadableNumbers) {
  for (const double far : {1e6, -1e6, 1e300}) {
    Request request = swapRequest();
    request.tasks[2].goal.y = far;
    const Response r = plan(request).response;
    EXPECT_EQ(r.status, Response::INVALID_GOAL) << r.message;
    EXPECT_NE(r.message.find("robot 'tug': goal"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("off the map"), std::string::npos) << r.message;
  }
  Request request = swapRequest();
  request.tasks[2].start.x = -1e300;
  const Response r = plan(request).response;
  EXPECT_NE(r.message.find("(-1e+300, "), std::string::npos) << "not cut off: " << r.message;
}

TEST_F(PlanningServiceTest, TimeLimitAboveMaxTimeLimitIsAnInvalidRequest) {
  for (const double limit : {1e12, PlannerConfig{}.max_time_limit + 1}) {
    Request request = swapRequest();
    request.time_limit = limit;
    const Response r = plan(request).response;
    EXPECT_EQ(r.status, Response::INVALID_REQUEST) << r.message;
    EXPECT_NE(r.message.find("max_time_limit (60 s)"), std::string::npos) << r.message;
  }
  for (const double limit : {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN(), -2.0}) {
    Request request = swapRequest();
    request.time_limit = limit;
    const Response r = plan(request).response;
    EXPECT_EQ(r.status, Response::INVALID_REQUEST) << r.message;
    EXPECT_NE(r.message.find("time_limit must be > 0"), std::string::npos) << r.message;
  }
  Request request = swapRequest();
  request.time_limit = PlannerConfig{}.max_time_limit;  // the maximum itself is fine
  expectValidPlan(request, plan(request).response);
}

TEST_F(PlanningServiceTest, AFootprintLargerThanTheMapIsRejectedAtOnce) {
  // A registry entry of 1e6 m: computing its cells would never end; the map is 6 m x 3 m.
  auto fleet = registry();
  fleet.robots[1] = circleFootprint("amr_2", 1e6);
  geometry_msgs::Point32 a, b, c;  // a small triangle 1 km from the robot's origin
  a.x = 1000, a.y = 0, b.x = 1000.2f, b.y = 0, c.x = 1000, c.y = 0.2f;
  fleet.robots[2].type = fleet_planner::RobotFootprint::POLYGON;
  fleet.robots[2].points = {a, b, c};
  service.setFootprints(fleet);
  const auto t0 = std::chrono::steady_clock::now();
  const Response r = plan(swapRequest()).response;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 2.0);
  EXPECT_EQ(r.status, Response::INVALID_REQUEST) << r.message;
  EXPECT_EQ(r.robots[1].status, RobotResultMsg::INVALID_FOOTPRINT) << r.robots[1].message;
  EXPECT_NE(r.robots[1].message.find("robot 'amr_2': footprint"), std::string::npos) << r.robots[1].message;
  EXPECT_NE(r.robots[1].message.find("larger than the map (6 m x 3 m)"), std::string::npos) << r.robots[1].message;
  EXPECT_EQ(r.robots[2].status, RobotResultMsg::INVALID_FOOTPRINT) << r.robots[2].message;
  // A footprint that only fits turned a quarter is not rejected by size: a 5.5 m x 0.4 m block
  // on a 6 m x 3 m map fits along x.
  fleet = registry();
  fleet.robots[2] = blockFootprint("tug", -0.2, 0.2, -2.75, 2.75);
  service.setFootprints(fleet);
  const Response turned = plan(swapRequest()).response;
  EXPECT_NE(turned.robots[2].status, RobotResultMsg::INVALID_FOOTPRINT) << turned.robots[2].message;
}

TEST_F(PlanningServiceTest, TimeSpentWaitingCountsAgainstTheTimeLimit) {
  // The node passes the time it took the call up: a call that waited its whole time limit for
  // the planner gets TIMEOUT, not a fresh time limit.
  Request request = swapRequest();
  request.time_limit = 5.0;
  const auto received = std::chrono::steady_clock::now() - std::chrono::seconds(6);
  const Response r = service.plan(request, nullptr, nullptr, received).response;
  EXPECT_EQ(r.status, Response::TIMEOUT) << r.message;
  EXPECT_GE(r.statistics.total_time, 6.0);
}

}  // namespace
}  // namespace fleet_planner::test
