#include "fleet_planner/io/plan_io.h"

#include "fleet_planner/model/robot_cells.h"

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fleet_planner/runtime/errors.h"
#include "io_helpers.h"

namespace fleet_planner {

namespace {

constexpr const char* kFormat = "fleet_planner/plan/1";

std::vector<GridPose> targetsOf(const Instance& instance, const Plan& plan) { return planTargets(instance, plan); }

Path readPath(const io::YamlMapping& entry, const std::string& who) {
  const io::YamlField& field = entry.require("path");
  if (!field.node.IsSequence() || field.node.size() == 0) {
    throw ParseError(entry.file(), field.line, who + " path must be a non-empty list of states");
  }
  Path path;
  for (std::size_t t = 0; t < field.node.size(); ++t) {
    const YAML::Node state = field.node[t];
    const int line = io::yamlLine(state, field.line);
    const std::string what = who + " state " + std::to_string(t);
    if (!state.IsSequence() || state.size() != 3) {
      throw ParseError(entry.file(), line, what + " must be a list [x, y, heading]");
    }
    GridPose pose{io::yamlIntegral(state[0], entry.file(), line, what + " x"),
                  io::yamlIntegral(state[1], entry.file(), line, what + " y"),
                  io::yamlIntegral(state[2], entry.file(), line, what + " heading")};
    if (!validHeading(pose.heading)) {
      throw ParseError(entry.file(), line,
                       what + " heading must be 0..3, got " + std::to_string(pose.heading));
    }
    path.push_back(pose);
  }
  return path;
}

/// Throws if an optional metric is present and differs from `actual`.
void checkMetric(const io::YamlMapping& fields, const std::string& key, long long actual,
                 const std::string& what) {
  const io::YamlField* field = fields.find(key);
  if (field == nullptr) return;
  const int written = fields.integral(*field, what);
  if (written != actual) {
    throw ParseError(
        fields.file(), field->line,
        what + " is " + std::to_string(written) + " but the paths give " + std::to_string(actual));
  }
}

}  // namespace

std::string planToYaml(const Instance& instance, const Plan& plan, bool backward_moves) {
  if (plan.paths.size() != instance.robots.size()) {
    throw InvalidInput("plan has " + std::to_string(plan.paths.size()) + " paths for " +
                       std::to_string(instance.robots.size()) + " robots");
  }
  for (std::size_t i = 0; i < plan.paths.size(); ++i) {
    if (plan.paths[i].empty()) {
      throw InvalidInput(robotLabel(instance.robots[i]) + " has an empty path");
    }
  }
  const PlanMetrics metrics = planMetrics(plan, targetsOf(instance, plan));
  std::ostringstream out;
  out << "# fleet_planner plan: each path lists [x, y, heading] at time steps 0, 1, 2, ...\n"
      << "format: " << kFormat << "\n"
      << "soc: " << metrics.soc << "\n"
      << "makespan: " << metrics.makespan << "\n";
  if (backward_moves) out << "backward_moves: true\n";
  out << "robots:\n";
  for (std::size_t i = 0; i < plan.paths.size(); ++i) {
    const Robot& robot = instance.robots[i];
    out << "  - id: " << io::yamlScalar(robot.id) << "\n"
        << "    cost: " << pathCost(plan.paths[i], planTarget(robot, plan.paths[i])) << "\n"
        << "    path: [";
    const char* separator = "";
    for (const GridPose& s : plan.paths[i]) {
      out << separator << "[" << s.x << ", " << s.y << ", " << s.heading << "]";
      separator = ", ";
    }
    out << "]\n";
  }
  return out.str();
}

void savePlan(const Instance& instance, const Plan& plan, const std::string& path, bool backward_moves) {
  io::writeTextFile(path, planToYaml(instance, plan, backward_moves));
}

Plan loadPlan(const std::string& path, const Instance& instance, bool* backward_moves) {
  const YAML::Node root = io::loadYamlFile(path);
  const io::YamlMapping top(root, path, 0, "the plan", {"format", "soc", "makespan", "backward_moves", "robots"});
  bool backward = false;
  if (const io::YamlField* b = top.find("backward_moves")) {
    const std::string text = b->node.IsScalar() ? b->node.Scalar() : "";
    if (text != "true" && text != "false")
      throw ParseError(path, b->line, "backward_moves must be true or false, got " + io::quoted(text));
    backward = text == "true";
  }
  if (backward_moves) *backward_moves = backward;
  const io::YamlField& format = top.require("format");
  const std::string format_text = format.node.IsScalar() ? format.node.Scalar() : "";
  if (format_text != kFormat) {
    throw ParseError(path, format.line,
                     "format must be " + std::string(kFormat) + ", got " + io::quoted(format_text));
  }

  std::map<std::string, std::size_t> index_of;
  for (std::size_t i = 0; i < instance.robots.size(); ++i) index_of[instance.robots[i].id] = i;

  const io::YamlField& robots = top.require("robots");
  if (!robots.node.IsSequence()) throw ParseError(path, robots.line, "robots must be a list");
  Plan plan;
  plan.paths.resize(instance.robots.size());
  std::vector<int> seen_line(instance.robots.size(), 0);
  std::vector<io::YamlMapping> entries;
  entries.reserve(robots.node.size());
  for (std::size_t k = 0; k < robots.node.size(); ++k) {
    const YAML::Node node = robots.node[k];
    const int line = io::yamlLine(node, robots.line);
    entries.emplace_back(node, path, line, "robots[" + std::to_string(k) + "]",
                         std::vector<std::string>{"id", "cost", "path"});
    const io::YamlMapping& entry = entries.back();
    const io::YamlField& id_field = entry.require("id");
    const std::string id = entry.string(id_field, "robots[" + std::to_string(k) + "] id");
    const auto found = index_of.find(id);
    if (found == index_of.end()) {
      throw ParseError(path, id_field.line,
                       "robot id " + io::quoted(id) + " is not in the instance");
    }
    const std::size_t i = found->second;
    if (seen_line[i] != 0) {
      throw ParseError(path, id_field.line,
                       "robot " + io::quoted(id) + " has a second path (first on line " +
                           std::to_string(seen_line[i]) + ")");
    }
    seen_line[i] = id_field.line;
    plan.paths[i] = readPath(entry, "robot " + io::quoted(id));
  }
  for (std::size_t i = 0; i < instance.robots.size(); ++i) {
    if (seen_line[i] == 0) {
      throw ParseError(path, robots.line,
                       "robot " + io::quoted(instance.robots[i].id) + " has no path");
    }
  }

  for (const io::YamlMapping& entry : entries) {
    const std::size_t i = index_of.at(entry.require("id").node.Scalar());
    checkMetric(entry, "cost", pathCost(plan.paths[i], planTarget(instance.robots[i], plan.paths[i])),
                "cost of robot " + io::quoted(instance.robots[i].id));
  }
  const PlanMetrics metrics = planMetrics(plan, targetsOf(instance, plan));
  checkMetric(top, "soc", metrics.soc, "soc");
  checkMetric(top, "makespan", metrics.makespan, "makespan");
  return plan;
}

}  // namespace fleet_planner
