#include "fleet_planner/model/instance_check.h"

#include <set>
#include <sstream>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/model/footprint_cells.h"
#include "fleet_planner/model/graph_search.h"

namespace fleet_planner {

std::string poseProblem(const GridMap& map, const FootprintCells& cells, const GridPose& pose) {
  if (!validHeading(pose.heading)) return "has heading outside 0..3";
  if (!map.inside(pose.x, pose.y)) {
    return "is off the " + std::to_string(map.width()) + " x " + std::to_string(map.height()) + " map";
  }
  for (const Cell& c : cells.body(pose.heading).cells()) {
    const int x = pose.x + c.x, y = pose.y + c.y;
    if (!map.inside(x, y)) return "footprint leaves the map";
    if (map.blocked(x, y)) {
      return "footprint covers the blocked cell (" + std::to_string(x) + "," + std::to_string(y) + ")";
    }
  }
  return {};
}

namespace {

void checkPose(const GridMap& map, const Robot& robot, const FootprintCells& cells,
               const GridPose& pose, const char* what) {
  const std::string problem = poseProblem(map, cells, pose);
  if (problem.empty()) return;
  const std::string where = robotLabel(robot) + ": " + what + " " + toString(pose);
  throw InvalidInput(where + (problem.rfind("footprint", 0) == 0 ? ": " : " ") + problem);
}

}  // namespace

void validateInstance(const GridMap& map, const Instance& instance) {
  std::set<std::string> ids;
  for (const Robot& robot : instance.robots) {
    if (robot.id.empty()) throw InvalidInput(robotLabel(robot) + ": robot id is empty");
    if (!ids.insert(robot.id).second) throw InvalidInput(robotLabel(robot) + ": duplicate robot id");
    const std::string problem = footprintProblem(robot.footprint);
    if (!problem.empty()) throw InvalidInput(robotLabel(robot) + ": footprint: " + problem);
    const FootprintCells& cells = *sharedFootprintCells(robot.footprint);
    for (int h = 0; h < kHeadings; ++h) {
      const CellSet& body = cells.body(h);
      if (body.maxX() - body.minX() + 1 > map.width() || body.maxY() - body.minY() + 1 > map.height()) {
        throw InvalidInput(robotLabel(robot) + ": footprint (" + robot.footprint.describe() +
                           ") is larger than the " + std::to_string(map.width()) + " x " +
                           std::to_string(map.height()) + " map");
      }
    }
    checkPose(map, robot, cells, robot.start, "start");
    checkPose(map, robot, cells, robot.target, "target");
  }
}

std::string SolvabilityReport::summary() const {
  std::string out;
  for (const auto& p : problems) out += p.reason + "\n";
  return out;
}

SolvabilityReport checkSolvability(const Instance& instance, const FleetGraphs& graphs, const Deadline& deadline) {
  SolvabilityReport report;
  const int n = static_cast<int>(instance.robots.size());
  for (int i = 0; i < n; ++i) {
    if (deadline.expired()) {
      report.complete = false;
      return report;
    }
    const Robot& r = instance.robots[i];
    const StateGraph& g = graphs.graph(i);
    const StateId s = g.id(r.start), t = g.id(r.target);
    if (!g.valid(s)) {
      report.problems.push_back({i, -1, RobotProblem::Kind::InvalidStart,
                                 robotLabel(r) + ": start " + toString(r.start) + " is not a valid state"});
    } else if (!g.valid(t)) {
      report.problems.push_back({i, -1, RobotProblem::Kind::InvalidTarget,
                                 robotLabel(r) + ": target " + toString(r.target) + " is not a valid state"});
    } else if (!isReachable(g, s, t)) {
      report.problems.push_back({i, -1, RobotProblem::Kind::Unreachable, robotLabel(r) + ": target " + toString(r.target) +
                                        " is not reachable from start " + toString(r.start) +
                                        " for its footprint"});
    }
  }
  for (int i = 0; i < n; ++i) {
    if (deadline.expired()) {
      report.complete = false;
      return report;
    }
    for (int j = i + 1; j < n; ++j) {
      const Robot &a = instance.robots[i], &b = instance.robots[j];
      if (footprintsOverlap(graphs.cells(i), a.start, graphs.cells(j), b.start)) {
        report.problems.push_back({i, j, RobotProblem::Kind::StartsOverlap,
                                   robotLabel(a) + ": start overlaps the start of " + robotLabel(b)});
      }
      if (footprintsOverlap(graphs.cells(i), a.target, graphs.cells(j), b.target)) {
        report.problems.push_back({i, j, RobotProblem::Kind::TargetsOverlap,
                                   robotLabel(a) + ": target overlaps the target of " + robotLabel(b)});
      }
    }
  }
  return report;
}

}  // namespace fleet_planner
