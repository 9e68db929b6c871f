// Markers: what RViz shows of a plan.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "fleet_planner/ros/marker_builder.h"
#include "ros_test_util.h"

namespace fleet_planner::test {
namespace {

using visualization_msgs::Marker;

RobotPlacement placement(const fleet_planner::RobotFootprint& f, double x, double y, int subproblem) {
  RobotPlacement p;
  p.robot_id = f.robot_id;
  p.footprint = f;
  p.start.x = x, p.start.y = y;
  p.goal.x = x + 2, p.goal.y = y, p.goal.theta = M_PI / 2;
  p.subproblem = subproblem;
  return p;
}

fleet_planner::RobotTimeline timeline(const std::string& id, double x, double y) {
  fleet_planner::RobotTimeline t;
  t.robot_id = id;
  for (int k = 0; k <= 4; ++k) {
    fleet_planner::TimedState s;
    s.step = k, s.time = k * 0.5, s.x = x + (k < 4 ? 0.5 * k : 2.0), s.y = y;
    t.states.push_back(s);
  }
  return t;
}

const Marker* find(const visualization_msgs::MarkerArray& a, const std::string& ns, int id) {
  for (const auto& m : a.markers) {
    if (m.ns == ns && m.id == id) return &m;
  }
  return nullptr;
}

TEST(MarkerBuilder, StartsGoalsPathsAndLabelsPerRobot) {
  const std::vector<RobotPlacement> placements = {placement(circleFootprint("amr", 0.3), 1, 1, 0),
                                                  placement(blockFootprint("tug", -0.4, 0.4, -0.2, 0.2), 1, 3, 1)};
  fleet_planner::SubproblemInfo s0, s1;
  s0.index = 0, s0.cluster = 0, s0.level = 0;
  s1.index = 1, s1.cluster = 0, s1.level = 1;
  MarkerStyle style;
  style.planned_frame_suffix = "planned";
  const auto array = buildPlanMarkers(placements, {timeline("amr", 1, 1), timeline("tug", 1, 3)}, {s0, s1}, style);

  ASSERT_FALSE(array.markers.empty());
  EXPECT_EQ(array.markers.front().action, Marker::DELETEALL);
  for (int i = 0; i < 2; ++i) {
    for (const char* ns : {"start", "goal", "heading", "label", "path", "planned"}) {
      EXPECT_NE(find(array, ns, i), nullptr) << ns << " " << i;
    }
  }
  // The block's start outline: its 4 corners around (1, 3), closed.
  const Marker* tug = find(array, "start", 1);
  ASSERT_EQ(tug->points.size(), 5u);
  EXPECT_NEAR(tug->points[0].x, 1.4, 1e-9);
  EXPECT_NEAR(tug->points[0].y, 3.2, 1e-9);
  EXPECT_EQ(tug->header.frame_id, "map");
  // Its goal is turned by 90 degrees: the corner (0.4, 0.2) lands at (3 - 0.2, 3 + 0.4).
  const Marker* goal = find(array, "goal", 1);
  EXPECT_NEAR(goal->points[0].x, 2.8, 1e-9);
  EXPECT_NEAR(goal->points[0].y, 3.4, 1e-9);
  EXPECT_EQ(goal->points.size() % 2, 0u);  // dashes
  // Labels name the subproblem, cluster and level.
  EXPECT_NE(find(array, "label", 1)->text.find("sub 1 | cluster 0 level 1"), std::string::npos);
  EXPECT_EQ(find(array, "label", 0)->text.rfind("amr", 0), 0u);
  // Paths drop repeated positions (waits, turns).
  EXPECT_EQ(find(array, "path", 0)->points.size(), 5u);
  // Footprints in the planned frames, for playback.
  EXPECT_EQ(find(array, "planned", 0)->header.frame_id, "amr/planned");
  EXPECT_TRUE(find(array, "planned", 0)->frame_locked);
  // Subproblems have different colours.
  const auto &c0 = find(array, "start", 0)->color, &c1 = find(array, "start", 1)->color;
  EXPECT_GT(std::abs(c0.r - c1.r) + std::abs(c0.g - c1.g) + std::abs(c0.b - c1.b), 0.3);
}

TEST(MarkerBuilder, WithoutTimelinesOrPlaybackThereAreNoPathsOrPlannedFrames) {
  const auto array = buildPlanMarkers({placement(circleFootprint("amr", 0.3), 1, 1, -1)}, {}, {}, MarkerStyle{});
  EXPECT_EQ(find(array, "path", 0), nullptr);
  EXPECT_EQ(find(array, "planned", 0), nullptr);
  ASSERT_NE(find(array, "start", 0), nullptr);
  EXPECT_EQ(find(array, "start", 0)->points.size(), 33u);  // a closed 32-gon
  EXPECT_EQ(find(array, "label", 0)->text, "amr");
}

TEST(MarkerBuilder, ColoursAreValidAndDistinctForNearbySubproblems) {
  std::set<std::tuple<int, int, int>> seen;
  for (int s = -1; s < 12; ++s) {
    const auto c = subproblemColour(s, 0.5);
    for (double v : {c.r, c.g, c.b}) {
      EXPECT_GE(v, 0.0);
      EXPECT_LE(v, 1.0);
    }
    EXPECT_FLOAT_EQ(c.a, 0.5f);
    seen.insert({static_cast<int>(c.r * 20), static_cast<int>(c.g * 20), static_cast<int>(c.b * 20)});
  }
  EXPECT_EQ(seen.size(), 13u);
}

}  // namespace
}  // namespace fleet_planner::test

namespace fleet_planner {
namespace {

TEST(ExecutionMarkers, BlockedWaitingLateAndArrivedRobotsAreMarkedOnTheirFrames) {
  using Robot = fleet_planner::RobotExecution;
  fleet_planner::FleetExecution execution;
  auto robot = [&](const std::string& id, std::uint8_t state, const std::string& by, double late) {
    Robot r;
    r.robot_id = id, r.state = state, r.blocked_by = by, r.lateness = late;
    execution.robots.push_back(r);
  };
  robot("a", Robot::BLOCKED, "b", 12.0);
  robot("b", Robot::DRIVING, "", 1.0);  // on time: no marker
  robot("c", Robot::WAITING, "a", 0.0);
  robot("d", Robot::DRIVING, "", 9.5);
  robot("e", Robot::ARRIVED, "", 0.0);
  const auto markers = buildExecutionMarkers(execution, "base_link", 5.0);
  ASSERT_EQ(markers.markers.size(), 5u);
  EXPECT_EQ(markers.markers[0].action, visualization_msgs::Marker::DELETEALL);
  std::map<std::string, std::string> text;
  for (std::size_t i = 1; i < markers.markers.size(); ++i) {
    const auto& m = markers.markers[i];
    EXPECT_TRUE(m.frame_locked);
    text[m.header.frame_id] = m.text;
  }
  EXPECT_EQ(text["a/base_link"], "BLOCKED by b");
  EXPECT_EQ(text["c/base_link"], "waits for a");
  EXPECT_EQ(text["d/base_link"], "late 9 s");
  EXPECT_EQ(text["e/base_link"], "arrived");
  EXPECT_EQ(text.count("b/base_link"), 0u);
}

}  // namespace
}  // namespace fleet_planner
