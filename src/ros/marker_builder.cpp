#include "fleet_planner/ros/marker_builder.h"

#include <cmath>

namespace fleet_planner {

namespace {

constexpr double kPi = 3.14159265358979323846;

geometry_msgs::Point point(double x, double y, double z = 0.0) {
  geometry_msgs::Point p;
  p.x = x, p.y = y, p.z = z;
  return p;
}

geometry_msgs::Point placed(const geometry_msgs::Point& p, const geometry_msgs::Pose2D& pose, double z) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  return point(pose.x + c * p.x - s * p.y, pose.y + s * p.x + c * p.y, z);
}

visualization_msgs::Marker marker(const MarkerStyle& style, const std::string& ns, int id, int type) {
  visualization_msgs::Marker m;
  m.header.frame_id = style.map_frame;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = style.line_width;
  return m;
}

std::string labelOf(const RobotPlacement& p, const std::vector<fleet_planner::SubproblemInfo>& subproblems) {
  std::string label = p.robot_id;
  if (p.subproblem >= 0 && p.subproblem < static_cast<int>(subproblems.size())) {
    const auto& s = subproblems[p.subproblem];
    label += "\nsub " + std::to_string(s.index) + " | cluster " + std::to_string(s.cluster) + " level " +
             std::to_string(s.level);
  }
  return label;
}

}  // namespace

std_msgs::ColorRGBA subproblemColour(int subproblem, double alpha) {
  std_msgs::ColorRGBA c;
  c.a = alpha;
  if (subproblem < 0) {
    c.r = c.g = c.b = 0.6;
    return c;
  }
  // Golden-ratio hue steps: neighbouring indices get far-apart hues. HSV with s = 0.75, v = 0.9.
  const double h = std::fmod(0.1 + 0.618033988749895 * subproblem, 1.0) * 6.0;
  const double v = 0.9, s = 0.75, f = h - std::floor(h);
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  const double rgb[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
  const int i = static_cast<int>(h) % 6;
  c.r = rgb[i][0], c.g = rgb[i][1], c.b = rgb[i][2];
  return c;
}

std::vector<geometry_msgs::Point> footprintOutline(const fleet_planner::RobotFootprint& f) {
  std::vector<geometry_msgs::Point> out;
  switch (f.type) {
    case fleet_planner::RobotFootprint::CIRCLE:
      for (int k = 0; k < 32; ++k) {
        const double a = 2 * kPi * k / 32;
        out.push_back(point(f.radius * std::cos(a), f.radius * std::sin(a)));
      }
      break;
    case fleet_planner::RobotFootprint::BLOCK:
      out = {point(f.max_x, f.max_y), point(f.min_x, f.max_y), point(f.min_x, f.min_y), point(f.max_x, f.min_y)};
      break;
    default:
      for (const auto& p : f.points) out.push_back(point(p.x, p.y));
  }
  if (!out.empty()) out.push_back(out.front());
  return out;
}

visualization_msgs::MarkerArray buildPlanMarkers(const std::vector<RobotPlacement>& placements,
                                                 const std::vector<fleet_planner::RobotTimeline>& timelines,
                                                 const std::vector<fleet_planner::SubproblemInfo>& subproblems,
                                                 const MarkerStyle& style) {
  visualization_msgs::MarkerArray array;
  visualization_msgs::Marker clear;
  clear.header.frame_id = style.map_frame;
  clear.action = visualization_msgs::Marker::DELETEALL;
  array.markers.push_back(clear);

  for (int i = 0; i < static_cast<int>(placements.size()); ++i) {
    const RobotPlacement& p = placements[i];
    const auto outline = footprintOutline(p.footprint);
    const auto colour = subproblemColour(p.subproblem);

    auto start = marker(style, "start", i, visualization_msgs::Marker::LINE_STRIP);
    for (const auto& q : outline) start.points.push_back(placed(q, p.start, 0.02));
    start.color = colour;
    array.markers.push_back(start);

    auto goal = marker(style, "goal", i, visualization_msgs::Marker::LINE_LIST);  // dashed
    for (std::size_t k = 0; k + 1 < outline.size(); ++k) {
      const auto &a = outline[k], &b = outline[k + 1];
      for (int d = 0; d < 4; d += 2) {  // two dashes per edge
        goal.points.push_back(placed(point(a.x + (b.x - a.x) * d / 4, a.y + (b.y - a.y) * d / 4), p.goal, 0.02));
        goal.points.push_back(
            placed(point(a.x + (b.x - a.x) * (d + 1) / 4, a.y + (b.y - a.y) * (d + 1) / 4), p.goal, 0.02));
      }
    }
    goal.color = subproblemColour(p.subproblem, 0.8);
    array.markers.push_back(goal);

    auto heading = marker(style, "heading", i, visualization_msgs::Marker::ARROW);
    double reach = 0.0;
    for (const auto& q : outline) reach = std::max(reach, std::hypot(q.x, q.y));
    heading.points = {placed(point(0, 0), p.start, 0.03), placed(point(reach, 0), p.start, 0.03)};
    heading.scale.x = style.line_width;       // shaft diameter
    heading.scale.y = 3 * style.line_width;   // head diameter
    heading.scale.z = 3 * style.line_width;   // head length
    heading.color = colour;
    array.markers.push_back(heading);

    auto label = marker(style, "label", i, visualization_msgs::Marker::TEXT_VIEW_FACING);
    label.pose.position = point(p.start.x, p.start.y + reach + style.text_height, 0.1);
    label.scale.z = style.text_height;
    label.color = colour;
    label.text = labelOf(p, subproblems);
    array.markers.push_back(label);

    for (const auto& timeline : timelines) {
      if (timeline.robot_id != p.robot_id || timeline.states.size() < 2) continue;
      auto path = marker(style, "path", i, visualization_msgs::Marker::LINE_STRIP);
      for (const auto& s : timeline.states) {
        if (path.points.empty() || path.points.back().x != s.x || path.points.back().y != s.y) {
          path.points.push_back(point(s.x, s.y, 0.01));
        }
      }
      path.color = subproblemColour(p.subproblem, 0.6);
      if (path.points.size() >= 2) array.markers.push_back(path);

      if (!style.planned_frame_suffix.empty()) {
        auto moving = marker(style, "planned", i, visualization_msgs::Marker::LINE_STRIP);
        moving.header.frame_id = p.robot_id + "/" + style.planned_frame_suffix;
        moving.frame_locked = true;  // re-transformed every frame: it follows the playback
        moving.points = outline;
        moving.points.push_back(point(0, 0));
        moving.points.push_back(point(reach, 0));  // a heading tick inside the outline
        moving.scale.x = 2 * style.line_width;
        moving.color = colour;
        array.markers.push_back(moving);
      }
    }
  }
  return array;
}

visualization_msgs::MarkerArray buildExecutionMarkers(const fleet_planner::FleetExecution& execution,
                                                      const std::string& base_frame, double late_warning) {
  using Robot = fleet_planner::RobotExecution;
  visualization_msgs::MarkerArray out;
  visualization_msgs::Marker clear;
  clear.ns = "execution";
  clear.action = visualization_msgs::Marker::DELETEALL;
  out.markers.push_back(clear);
  auto colour = [](double r, double g, double b) {
    std_msgs::ColorRGBA c;
    c.r = r, c.g = g, c.b = b, c.a = 1.0;
    return c;
  };
  for (std::size_t i = 0; i < execution.robots.size(); ++i) {
    const Robot& r = execution.robots[i];
    std::string text;
    std_msgs::ColorRGBA c = colour(1.0, 0.55, 0.0);
    const std::string by = r.blocked_by.empty() ? "" : " " + r.blocked_by;
    if (r.state == Robot::BLOCKED) {
      text = "BLOCKED" + (by.empty() ? "" : " by" + by), c = colour(0.9, 0.1, 0.1);
    } else if (r.state == Robot::NO_POSE || r.state == Robot::OFF_PATH) {
      text = r.state == Robot::NO_POSE ? "NO POSE" : "OFF PATH", c = colour(0.9, 0.1, 0.1);
    } else if (r.state == Robot::ARRIVED) {
      text = "arrived", c = colour(0.1, 0.7, 0.2);
    } else if (r.state == Robot::WAITING && !by.empty()) {
      text = "waits for" + by;
    } else if (r.lateness > late_warning) {
      text = "late " + std::to_string(static_cast<int>(r.lateness)) + " s";
    }
    if (text.empty()) continue;
    visualization_msgs::Marker m;
    m.header.frame_id = r.robot_id + "/" + base_frame;
    m.frame_locked = true;
    m.ns = "execution";
    m.id = static_cast<int>(i);
    m.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
    m.action = visualization_msgs::Marker::ADD;
    m.pose.position.y = -0.45;
    m.pose.position.z = 0.5;
    m.pose.orientation.w = 1.0;
    m.scale.z = 0.3;
    m.color = c;
    m.text = text;
    out.markers.push_back(m);
  }
  return out;
}

}  // namespace fleet_planner
