/// The legality checker of a decomposition (see legality.h). It deliberately shares no code with
/// the decomposition: it replays the paper's "simplified scenario" directly. Subproblems are
/// solved one after another; while subproblem k is solved, every robot of an earlier subproblem
/// stands still at its target and every robot of a later subproblem at its start. Those
/// footprints become blocked cells, and each robot of subproblem k needs a path in its own
/// state graph whose states and swept cells avoid them (robots of the same subproblem ignore
/// each other: resolving those conflicts is the subproblem solver's job).
#include "fleet_planner/decomposition/legality.h"

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/obstacle_index.h"

namespace fleet_planner {

namespace {

LegalityReport fail(int subproblem, int robot, std::string message) {
  LegalityReport report;
  report.legal = false;
  report.subproblem = subproblem;
  report.robot = robot;
  report.message = std::move(message);
  return report;
}

std::string where(const Instance& instance, int robot, int subproblem) {
  return robotLabel(instance.robots[robot]) + " in subproblem " + std::to_string(subproblem);
}

/// Marks the cells of `robot`'s footprint at `pose` in the row-major grid `blocked`.
void markBody(const FleetGraphs& graphs, int robot, const GridPose& pose, int width, int height,
              std::vector<std::uint8_t>& blocked) {
  for (const Cell& d : graphs.cells(robot).body(pose.heading).cells()) {
    const int x = pose.x + d.x, y = pose.y + d.y;
    if (x >= 0 && y >= 0 && x < width && y < height) blocked[static_cast<std::size_t>(y) * width + x] = 1;
  }
}

/// Breadth-first search from `start` to `target` in `graph` over the edges whose swept cells
/// (at the source cell) avoid the blocked cells of `obstacles`. The caller has checked that the
/// start and target footprints are free; every other visited state's footprint lies inside the
/// sweep of the edge that reached it, so it is free too.
bool pathAvoiding(const StateGraph& graph, const ObstacleIndex& obstacles, StateId start, StateId target) {
  if (start == target) return true;
  const FootprintCells& cells = graph.cells();
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(graph.stateIdCount()), 0);
  std::deque<StateId> queue{start};
  seen[start] = 1;
  while (!queue.empty()) {
    const StateId s = queue.front();
    queue.pop_front();
    const GridPose p = graph.pose(s);
    bool found = false;
    graph.forEachSuccessor(s, [&](Action a, StateId t) {
      if (found || seen[t] || obstacles.blocked(cells.swept(p.heading, a), {p.x, p.y})) return;
      seen[t] = 1;
      if (t == target) found = true;
      queue.push_back(t);
    });
    if (found) return true;
  }
  return false;
}

}  // namespace

LegalityReport checkLegality(const Instance& instance, const FleetGraphs& graphs,
                             const std::vector<std::vector<int>>& subproblems) {
  const int n = static_cast<int>(instance.robots.size());
  if (graphs.numRobots() != n) {
    return fail(-1, -1, "the fleet graphs have " + std::to_string(graphs.numRobots()) +
                            " robots but the instance has " + std::to_string(n));
  }

  // Coverage: every robot in exactly one subproblem; no empty subproblem.
  std::vector<int> owner(n, -1);
  for (int k = 0; k < static_cast<int>(subproblems.size()); ++k) {
    if (subproblems[k].empty()) return fail(k, -1, "subproblem " + std::to_string(k) + " is empty");
    for (int i : subproblems[k]) {
      if (i < 0 || i >= n) {
        return fail(k, i, "subproblem " + std::to_string(k) + " names robot index " + std::to_string(i) +
                              ", but the instance has " + std::to_string(n) + " robots");
      }
      if (owner[i] != -1) {
        return fail(k, i, robotLabel(instance.robots[i]) + " appears in subproblem " + std::to_string(owner[i]) +
                              " and again in subproblem " + std::to_string(k));
      }
      owner[i] = k;
    }
  }
  for (int i = 0; i < n; ++i) {
    if (owner[i] == -1) return fail(-1, i, robotLabel(instance.robots[i]) + " is in no subproblem");
  }
  if (n == 0) return {};

  // Every graph has the map's size; the blocked grid of subproblem k uses it too.
  const int width = graphs.graph(0).width(), height = graphs.graph(0).height();
  for (int k = 0; k < static_cast<int>(subproblems.size()); ++k) {
    std::vector<std::uint8_t> blocked(static_cast<std::size_t>(width) * height, 0);
    for (int j = 0; j < n; ++j) {
      if (owner[j] < k) markBody(graphs, j, instance.robots[j].target, width, height, blocked);
      if (owner[j] > k) markBody(graphs, j, instance.robots[j].start, width, height, blocked);
    }
    const ObstacleIndex obstacles(GridMap(width, height, std::move(blocked)), ObstacleIndex::Clearance::Chessboard);

    for (int i : subproblems[k]) {
      const Robot& robot = instance.robots[i];
      const StateGraph& graph = graphs.graph(i);
      const FootprintCells& cells = graph.cells();
      const StateId start = graph.id(robot.start), target = graph.id(robot.target);
      if (!graph.valid(start) || !graph.valid(target)) {
        return fail(k, i, where(instance, i, k) + ": its " + (graph.valid(start) ? "target" : "start") +
                              " is not a valid state of its own graph");
      }
      if (obstacles.blocked(cells.body(robot.start.heading), {robot.start.x, robot.start.y})) {
        return fail(k, i, where(instance, i, k) +
                              ": its start is covered by the footprint of a robot of another subproblem "
                              "(an earlier one at its target or a later one at its start)");
      }
      if (obstacles.blocked(cells.body(robot.target.heading), {robot.target.x, robot.target.y})) {
        return fail(k, i, where(instance, i, k) +
                              ": its target is covered by the footprint of a robot of another subproblem "
                              "(an earlier one at its target or a later one at its start)");
      }
      if (!pathAvoiding(graph, obstacles, start, target)) {
        return fail(k, i, where(instance, i, k) +
                              ": no path from start to target avoids the targets of earlier subproblems "
                              "and the starts of later subproblems");
      }
    }
  }
  return {};
}

}  // namespace fleet_planner
