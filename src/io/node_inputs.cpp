// The node's fleet and tasks files as an instance; see node_inputs.h.
#include "fleet_planner/io/node_inputs.h"

#include <cmath>
#include <map>

#include "fleet_planner/runtime/errors.h"
#include "io_helpers.h"

namespace fleet_planner {

namespace {

double sign(double v) { return v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0; }

/// One fleet entry's footprint in metres (padding applied).
Footprint readFleetFootprint(const io::YamlMapping& robot, const std::string& who) {
  const char* shapes[] = {"robot_radius", "footprint", "block"};
  const io::YamlField* shape = nullptr;
  std::string key;
  for (const char* k : shapes) {
    if (const io::YamlField* f = robot.find(k)) {
      if (shape != nullptr) throw ParseError(robot.file(), f->line, who + ": needs exactly one of robot_radius, footprint, block");
      shape = f, key = k;
    }
  }
  if (shape == nullptr) throw ParseError(robot.file(), robot.line(), who + ": needs one of robot_radius, footprint, block");
  double padding = 0.0;
  if (const io::YamlField* p = robot.find("footprint_padding")) padding = robot.number(*p, who + " footprint_padding");
  if (!(padding >= 0)) throw ParseError(robot.file(), robot.find("footprint_padding")->line, who + ": footprint_padding must be >= 0");
  if (key == "robot_radius") return Footprint::circle(robot.number(*shape, who + " robot_radius") + padding);
  if (key == "block") {
    const io::YamlMapping b(shape->node, robot.file(), shape->line, who + " block", {"min_x", "max_x", "min_y", "max_y"});
    auto n = [&](const char* k) { return b.number(b.require(k), who + " block " + k); };
    return Footprint::block(n("min_x") - padding, n("min_y") - padding, n("max_x") + padding, n("max_y") + padding);
  }
  if (!shape->node.IsSequence()) throw ParseError(robot.file(), shape->line, who + ": footprint must be a list of [x, y]");
  std::vector<Eigen::Vector2d> points;
  for (std::size_t i = 0; i < shape->node.size(); ++i) {
    const YAML::Node p = shape->node[i];
    const int line = io::yamlLine(p, shape->line);
    if (!p.IsSequence() || p.size() != 2) throw ParseError(robot.file(), line, who + ": footprint point must be [x, y]");
    const double x = io::yamlNumber(p[0], robot.file(), line, who + " footprint x");
    const double y = io::yamlNumber(p[1], robot.file(), line, who + " footprint y");
    points.emplace_back(x + sign(x) * padding, y + sign(y) * padding);
  }
  return Footprint::polygon(std::move(points));
}

Footprint scaled(Footprint f, double k) {
  f.radius *= k, f.min_x *= k, f.max_x *= k, f.min_y *= k, f.max_y *= k;
  for (auto& p : f.points) p *= k;
  return f;
}

/// A [x, y, yaw] pose (metres, radians, map frame) on the map: its cell, the nearest grid heading,
/// and the yaw when farther than `tolerance` from it.
GridPose placePose(const GridMap& map, const io::YamlMapping& task, const char* key, const std::string& who,
                   double tolerance, std::optional<double>& yaw) {
  const io::YamlField& f = task.require(key);
  if (!f.node.IsSequence() || f.node.size() != 3) throw ParseError(task.file(), f.line, who + ": " + key + " must be [x, y, yaw]");
  const double x = io::yamlNumber(f.node[0], task.file(), f.line, who + " " + key + " x");
  const double y = io::yamlNumber(f.node[1], task.file(), f.line, who + " " + key + " y");
  const double theta = io::yamlNumber(f.node[2], task.file(), f.line, who + " " + key + " yaw");
  const MapOrigin& o = map.origin();
  const double c = std::cos(o.yaw), s = std::sin(o.yaw);
  const double gx = (c * (x - o.x) + s * (y - o.y)) / map.resolution();
  const double gy = (-s * (x - o.x) + c * (y - o.y)) / map.resolution();
  if (!(gx >= 0 && gy >= 0 && gx < map.width() && gy < map.height())) {
    throw InvalidInput(who + " (" + task.file() + ":" + std::to_string(f.line) + "): " + key + " (" + std::to_string(x) +
                       ", " + std::to_string(y) + ") is off the map");
  }
  const double grid_yaw = std::remainder(theta - o.yaw, 2 * 3.141592653589793);
  GridPose pose{static_cast<int>(std::floor(gx)), static_cast<int>(std::floor(gy)), 0};
  double best = 1e9;
  for (int h = 0; h < kHeadings; ++h) {
    const double gap = std::abs(std::remainder(grid_yaw - headingYaw(h), 2 * 3.141592653589793));
    if (gap < best) best = gap, pose.heading = h;
  }
  if (best > tolerance) yaw = grid_yaw;
  return pose;
}

}  // namespace

Instance loadFleetTasks(const GridMap& map, const std::string& fleet_path, const std::string& tasks_path,
                        double heading_tolerance) {
  std::map<std::string, std::pair<Footprint, std::string>> fleet;
  {
    const YAML::Node root = io::loadYamlFile(fleet_path);
    const io::YamlMapping top(root, fleet_path, 1, "the fleet file", {"robots"});
    const io::YamlField& robots = top.require("robots");
    if (!robots.node.IsSequence()) throw ParseError(fleet_path, robots.line, "robots must be a list");
    for (std::size_t i = 0; i < robots.node.size(); ++i) {
      const int line = io::yamlLine(robots.node[i], robots.line);
      const io::YamlMapping r(robots.node[i], fleet_path, line, "robots[" + std::to_string(i) + "]",
                              {"id", "robot_radius", "footprint", "block", "footprint_padding"});
      const std::string id = r.string(r.require("id"), "robots[" + std::to_string(i) + "] id");
      const std::string who = "robot '" + id + "'";
      if (fleet.count(id)) throw ParseError(fleet_path, line, who + " is listed twice");
      const Footprint f = scaled(readFleetFootprint(r, who), 1.0 / map.resolution());
      const std::string problem = footprintProblem(f);
      if (!problem.empty()) throw ParseError(fleet_path, line, who + ": invalid footprint: " + problem);
      fleet.emplace(id, std::make_pair(f, fleet_path + ":" + std::to_string(line)));
    }
  }
  Instance instance;
  const YAML::Node root = io::loadYamlFile(tasks_path);
  const io::YamlMapping top(root, tasks_path, 1, "the tasks file", {"tasks"});
  const io::YamlField& tasks = top.require("tasks");
  if (!tasks.node.IsSequence() || tasks.node.size() == 0) throw ParseError(tasks_path, tasks.line, "tasks must be a non-empty list");
  for (std::size_t i = 0; i < tasks.node.size(); ++i) {
    const int line = io::yamlLine(tasks.node[i], tasks.line);
    const io::YamlMapping t(tasks.node[i], tasks_path, line, "tasks[" + std::to_string(i) + "]",
                            {"id", "start", "goal", "start_from_tf"});
    Robot robot;
    robot.id = t.string(t.require("id"), "tasks[" + std::to_string(i) + "] id");
    const std::string who = "robot '" + robot.id + "'";
    const auto found = fleet.find(robot.id);
    if (found == fleet.end()) throw ParseError(tasks_path, line, who + " is not in the fleet file " + fleet_path);
    if (t.find("start_from_tf") != nullptr) {
      throw ParseError(tasks_path, t.find("start_from_tf")->line, who + ": start_from_tf needs TF (the node); give a start");
    }
    robot.footprint = found->second.first;
    robot.source = tasks_path + ":" + std::to_string(line);
    robot.start = placePose(map, t, "start", who, heading_tolerance, robot.start_yaw);
    robot.target = placePose(map, t, "goal", who, heading_tolerance, robot.target_yaw);
    instance.robots.push_back(std::move(robot));
  }
  return instance;
}

}  // namespace fleet_planner
