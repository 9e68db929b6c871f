#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/io/instance_io.h"
#include "io_helpers.h"

namespace fleet_planner {

namespace {

GridPose readPose(const io::YamlMapping& robot, const std::string& key, const std::string& who) {
  const io::YamlField& field = robot.require(key);
  if (!field.node.IsSequence() || field.node.size() != 3) {
    throw ParseError(robot.file(), field.line, who + " " + key + " must be a list [x, y, heading]");
  }
  const char* const names[3] = {" x", " y", " heading"};
  int values[3];
  for (std::size_t i = 0; i < 3; ++i) {
    const YAML::Node element = field.node[i];
    values[i] = io::yamlIntegral(element, robot.file(), io::yamlLine(element, field.line),
                                 who + " " + key + names[i]);
  }
  if (!validHeading(values[2])) {
    throw ParseError(robot.file(), field.line,
                     who + " " + key + " heading must be 0..3, got " + std::to_string(values[2]));
  }
  return GridPose{values[0], values[1], values[2]};
}

Footprint readFootprint(const io::YamlMapping& robot, const std::string& who) {
  const io::YamlField& field = robot.require("footprint");
  const io::YamlMapping fp(field.node, robot.file(), field.line, who + " footprint",
                           {"type", "radius", "min_x", "min_y", "max_x", "max_y", "points"});
  const std::string type = fp.string(fp.require("type"), who + " footprint type");
  std::vector<std::string> keys;
  if (type == "circle") {
    keys = {"radius"};
  } else if (type == "block") {
    keys = {"min_x", "min_y", "max_x", "max_y"};
  } else if (type == "polygon") {
    keys = {"points"};
  } else {
    throw ParseError(
        robot.file(), fp.require("type").line,
        who + " footprint type must be circle, block or polygon, got " + io::quoted(type));
  }
  for (const char* key : {"radius", "min_x", "min_y", "max_x", "max_y", "points"}) {
    bool wanted = false;
    for (const auto& k : keys) wanted = wanted || k == key;
    if (!wanted && fp.find(key) != nullptr) {
      throw ParseError(robot.file(), fp.find(key)->line,
                       who + " footprint: key " + io::quoted(key) + " does not belong to a " +
                           type + " footprint");
    }
  }
  const auto number = [&](const char* key) {
    return fp.number(fp.require(key), who + " footprint " + key);
  };
  if (type == "circle") return Footprint::circle(number("radius"));
  if (type == "block") {
    return Footprint::block(number("min_x"), number("min_y"), number("max_x"), number("max_y"));
  }
  const io::YamlField& points = fp.require("points");
  if (!points.node.IsSequence()) {
    throw ParseError(robot.file(), points.line, who + " footprint points must be a list of [x, y]");
  }
  std::vector<Eigen::Vector2d> vertices;
  for (std::size_t i = 0; i < points.node.size(); ++i) {
    const YAML::Node point = points.node[i];
    const int line = io::yamlLine(point, points.line);
    if (!point.IsSequence() || point.size() != 2) {
      throw ParseError(robot.file(), line,
                       who + " footprint point " + std::to_string(i) + " must be a list [x, y]");
    }
    const std::string name = who + " footprint point " + std::to_string(i);
    vertices.emplace_back(io::yamlNumber(point[0], robot.file(), line, name + " x"),
                          io::yamlNumber(point[1], robot.file(), line, name + " y"));
  }
  return Footprint::polygon(std::move(vertices));
}

std::string poseYaml(const GridPose& pose) {
  return "[" + std::to_string(pose.x) + ", " + std::to_string(pose.y) + ", " +
         std::to_string(pose.heading) + "]";
}

std::string footprintYaml(const Footprint& fp) {
  using io::formatNumber;
  switch (fp.kind) {
    case Footprint::Kind::Circle:
      return "{type: circle, radius: " + formatNumber(fp.radius) + "}";
    case Footprint::Kind::Block:
      return "{type: block, min_x: " + formatNumber(fp.min_x) +
             ", min_y: " + formatNumber(fp.min_y) + ", max_x: " + formatNumber(fp.max_x) +
             ", max_y: " + formatNumber(fp.max_y) + "}";
    case Footprint::Kind::Polygon:
      break;
  }
  std::string points;
  for (const auto& p : fp.points) {
    points +=
        (points.empty() ? "[" : ", [") + formatNumber(p.x()) + ", " + formatNumber(p.y()) + "]";
  }
  return "{type: polygon, points: [" + points + "]}";
}

}  // namespace

Instance parseScenario(std::istream& in, const std::string& path) {
  const YAML::Node root = io::parseYaml(in, path);
  const io::YamlMapping top(root, path, 0, "the scenario", {"map", "robots"});
  Instance instance;
  if (const io::YamlField* map = top.find("map")) {
    instance.map_file = io::resolveRelativeTo(path, top.string(*map, "map"));
  }
  const io::YamlField& robots = top.require("robots");
  if (!robots.node.IsSequence() || robots.node.size() == 0) {
    throw ParseError(path, robots.line, "robots must be a non-empty list");
  }
  std::map<std::string, int> id_lines;
  for (std::size_t i = 0; i < robots.node.size(); ++i) {
    const YAML::Node node = robots.node[i];
    const int line = io::yamlLine(node, robots.line);
    const io::YamlMapping fields(node, path, line, "robots[" + std::to_string(i) + "]",
                                 {"id", "footprint", "start", "target", "start_yaw", "target_yaw"});
    Robot robot;
    const io::YamlField& id = fields.require("id");
    robot.id = fields.string(id, "robots[" + std::to_string(i) + "] id");
    robot.source = path + ":" + std::to_string(line);
    const std::string who = "robot " + io::quoted(robot.id);
    const auto inserted = id_lines.emplace(robot.id, id.line);
    if (!inserted.second) {
      throw ParseError(path, id.line,
                       "duplicate robot id " + io::quoted(robot.id) + " (first on line " +
                           std::to_string(inserted.first->second) + ")");
    }
    robot.footprint = readFootprint(fields, who);
    const std::string problem = footprintProblem(robot.footprint);
    if (!problem.empty()) {
      throw ParseError(path, fields.require("footprint").line,
                       who + ": invalid footprint: " + problem);
    }
    robot.start = readPose(fields, "start", who);
    robot.target = readPose(fields, "target", who);
    // Optional yaws (radians) off the grid headings: the plan turns from / to them in place.
    if (const io::YamlField* yaw = fields.find("start_yaw")) robot.start_yaw = fields.number(*yaw, who + " start_yaw");
    if (const io::YamlField* yaw = fields.find("target_yaw")) robot.target_yaw = fields.number(*yaw, who + " target_yaw");
    instance.robots.push_back(std::move(robot));
  }
  return instance;
}

Instance loadScenario(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ParseError(path, 0, "cannot open file");
  return parseScenario(in, path);
}

std::string scenarioToYaml(const Instance& instance, const std::string& map_file_as_written) {
  if (instance.robots.empty()) throw InvalidInput("cannot write a scenario without robots");
  std::ostringstream out;
  out << "# fleet_planner scenario: start and target are [x, y, heading];"
         " heading 0 = +x, 1 = -x, 2 = +y, 3 = -y\n";
  if (!map_file_as_written.empty()) out << "map: " << io::yamlScalar(map_file_as_written) << "\n";
  out << "robots:\n";
  std::set<std::string> ids;
  for (const Robot& robot : instance.robots) {
    if (robot.id.empty()) throw InvalidInput("cannot write a robot with an empty id");
    if (!ids.insert(robot.id).second) {
      throw InvalidInput("cannot write the scenario: duplicate robot id " + io::quoted(robot.id));
    }
    out << "  - id: " << io::yamlScalar(robot.id) << "\n"
        << "    footprint: " << footprintYaml(robot.footprint) << "\n"
        << "    start: " << poseYaml(robot.start) << "\n"
        << "    target: " << poseYaml(robot.target) << "\n";
    if (robot.start_yaw) out << "    start_yaw: " << io::formatNumber(*robot.start_yaw) << "\n";
    if (robot.target_yaw) out << "    target_yaw: " << io::formatNumber(*robot.target_yaw) << "\n";
  }
  return out.str();
}

void saveScenario(const Instance& instance, const std::string& path) {
  io::writeTextFile(path, scenarioToYaml(instance, instance.map_file));
}

namespace {

// A scenario whatever the file is called (`generate --out fleet.scen` writes one): its first
// non-blank line is a YAML comment, a document start or a top-level key, where a line of a
// benchmark pool starts with a robot kind ("Circle", "Block_2D").
bool looksLikeScenario(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    const std::string head = line.substr(first);
    return head[0] == '#' || head[0] == '{' || head.rfind("---", 0) == 0 || head.rfind("map:", 0) == 0 ||
           head.rfind("robots:", 0) == 0;
  }
  return false;
}

}  // namespace

Instance loadInstance(const std::string& path) {
  if (io::hasYamlExtension(path) || looksLikeScenario(path)) return loadScenario(path);
  return loadBenchmarkInstance(path);
}

}  // namespace fleet_planner
