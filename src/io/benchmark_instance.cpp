#include <fstream>
#include <istream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/io/instance_io.h"
#include "io_helpers.h"

namespace fleet_planner {

namespace {

const std::vector<std::string> kCircleSizes{"r"};
const std::vector<std::string> kBlockSizes{"min_x", "min_y", "max_x", "max_y"};
const std::vector<std::string> kPoseFields{"sx", "sy", "so", "tx", "ty", "to"};

/// One robot line being parsed, for messages.
struct LineContext {
  const std::string& source;
  int line;

  double number(const std::string& token, const std::string& name) const {
    double value = 0.0;
    if (!io::parseNumber(token, &value)) {
      throw ParseError(source, line, name + " is not a finite number: " + io::quoted(token));
    }
    return value;
  }

  int integral(const std::string& token, const std::string& name) const {
    const double value = number(token, name);
    int result = 0;
    if (!io::parseIntegral(token, &result)) {
      throw ParseError(source, line, name + " must be an integer, got " + io::formatNumber(value));
    }
    return result;
  }

  GridPose pose(const std::string* tokens, const std::string* names) const {
    GridPose pose{integral(tokens[0], names[0]), integral(tokens[1], names[1]),
                  integral(tokens[2], names[2])};
    if (!validHeading(pose.heading)) {
      throw ParseError(
          source, line,
          "heading " + names[2] + " must be 0..3, got " + std::to_string(pose.heading));
    }
    return pose;
  }
};

std::vector<std::string> splitWords(const std::string& line) {
  std::istringstream split(line);
  std::vector<std::string> words;
  for (std::string word; split >> word;) words.push_back(word);
  return words;
}

}  // namespace

Instance parseBenchmarkInstance(std::istream& in, const std::string& source) {
  Instance instance;
  std::map<std::string, int> id_lines;
  int line_number = 0;
  int with_id = -1;  // -1 until the first robot line decides
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    const std::vector<std::string> words = splitWords(line);  // a trailing '\r' is a blank
    if (words.empty()) continue;
    const LineContext context{source, line_number};

    const std::string& kind = words[0];
    const std::vector<std::string>* size_names = nullptr;
    if (kind == "Circle") {
      size_names = &kCircleSizes;
    } else if (kind == "Block_2D") {
      size_names = &kBlockSizes;
    } else {
      throw ParseError(source, line_number,
                       "unknown robot kind " + io::quoted(kind) + " (expected Circle or Block_2D)");
    }
    const std::size_t without_id = 1 + size_names->size() + kPoseFields.size();
    if (words.size() != without_id && words.size() != without_id + 1) {
      throw ParseError(source, line_number,
                       kind + " line has " + std::to_string(words.size()) + " fields, expected " +
                           std::to_string(without_id) + " (without id) or " +
                           std::to_string(without_id + 1) + " (with id)");
    }
    const int has_id = words.size() == without_id + 1 ? 1 : 0;
    if (with_id >= 0 && has_id != with_id) {
      throw ParseError(source, line_number,
                       std::string("line ") + (has_id ? "has" : "lacks") +
                           " the id column, unlike the robot lines before it");
    }
    with_id = has_id;

    Robot robot;
    robot.id = has_id ? words[1] : std::to_string(instance.robots.size());
    robot.source = source + ":" + std::to_string(line_number);
    const std::string* fields = words.data() + 1 + has_id;
    std::vector<double> sizes;
    for (std::size_t i = 0; i < size_names->size(); ++i) {
      sizes.push_back(context.number(fields[i], (*size_names)[i]));
    }
    robot.footprint = kind == "Circle" ? Footprint::circle(sizes[0])
                                       : Footprint::block(sizes[0], sizes[1], sizes[2], sizes[3]);
    fields += size_names->size();
    robot.start = context.pose(fields, kPoseFields.data());
    robot.target = context.pose(fields + 3, kPoseFields.data() + 3);

    const std::string problem = footprintProblem(robot.footprint);
    if (!problem.empty()) {
      throw ParseError(source, line_number,
                       "robot " + io::quoted(robot.id) + ": invalid footprint: " + problem);
    }
    const auto inserted = id_lines.emplace(robot.id, line_number);
    if (!inserted.second) {
      throw ParseError(source, line_number,
                       "duplicate robot id " + io::quoted(robot.id) + " (first on line " +
                           std::to_string(inserted.first->second) + ")");
    }
    instance.robots.push_back(std::move(robot));
  }
  if (instance.robots.empty()) throw ParseError(source, 0, "no robots in the file");
  return instance;
}

Instance loadBenchmarkInstance(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ParseError(path, 0, "cannot open file");
  return parseBenchmarkInstance(in, path);
}

}  // namespace fleet_planner
