// Robots that may have to step aside; see step_aside.h.
#include "fleet_planner/layered/step_aside.h"

#include <algorithm>
#include <cstdlib>

#include "fleet_planner/model/graph_search.h"
#include "path_steps.h"

namespace fleet_planner {

namespace {

// The poses of one shortest path from the robot's start to its target (empty if none).
std::vector<GridPose> shortestPath(const StateGraph& graph, const Robot& robot) {
  const StateId start = graph.id(robot.start), target = graph.id(robot.target);
  if (!graph.valid(start) || !graph.valid(target)) return {};
  const std::vector<std::int32_t> dist = distancesTo(graph, target);
  if (dist[start] < 0) return {};
  std::vector<GridPose> path{graph.pose(start)};
  for (StateId s = start; s != target;) {
    StateId next = kNoState;
    graph.forEachSuccessor(s, [&](Action, StateId n) {
      if (next == kNoState && dist[n] == dist[s] - 1) next = n;
    });
    s = next;
    path.push_back(graph.pose(s));
  }
  return path;
}

}  // namespace

std::vector<StaticFootprint> robotsInTheWay(const Instance& instance, const FleetGraphs& graphs,
                                            const std::vector<int>& robots,
                                            const std::vector<StaticFootprint>& standing, int margin,
                                            std::size_t max_count) {
  // Per standing robot: its smallest gap (cells, Chebyshev, beyond both radii) to a way.
  constexpr int kFar = 1 << 30;
  std::vector<int> gap(standing.size(), kFar);
  for (int r : robots) {
    const std::vector<GridPose> path = shortestPath(graphs.graph(r), instance.robots[r]);
    const int own = path_steps::radiusOf(graphs.cells(r));
    for (std::size_t j = 0; j < standing.size(); ++j) {
      const GridPose& at = standing[j].pose;
      const int reach = own + path_steps::radiusOf(graphs.cells(standing[j].robot));
      for (const GridPose& p : path) {
        gap[j] = std::min(gap[j], std::max(std::abs(p.x - at.x), std::abs(p.y - at.y)) - reach);
      }
    }
  }
  std::vector<std::size_t> near;
  for (std::size_t j = 0; j < standing.size(); ++j) {
    if (gap[j] <= margin) near.push_back(j);
  }
  std::stable_sort(near.begin(), near.end(), [&](std::size_t a, std::size_t b) { return gap[a] < gap[b]; });
  if (near.size() > max_count) near.resize(max_count);
  std::sort(near.begin(), near.end());
  std::vector<StaticFootprint> out;
  for (std::size_t j : near) out.push_back(standing[j]);
  return out;
}

std::vector<StaticFootprint> robotsOnPaths(const FleetGraphs& graphs, const std::vector<int>& robots,
                                           const std::vector<Path>& paths,
                                           const std::vector<StaticFootprint>& standing) {
  std::vector<StaticFootprint> out;
  if (robots.empty()) return out;
  const ActionModel model = graphs.graph(robots[0]).actionModel();
  for (const StaticFootprint& f : standing) {
    const FootprintCells& B = graphs.cells(f.robot);
    const Path still{f.pose};
    const path_steps::Box box = path_steps::boxOf(B, still);
    bool met = false;
    for (std::size_t i = 0; i < robots.size() && !met; ++i) {
      const Path& p = paths[i];
      if (p.empty()) continue;
      const FootprintCells& A = graphs.cells(robots[i]);
      if (!path_steps::boxOf(A, p).meets(box)) continue;
      for (int t = 0; t < static_cast<int>(p.size()) && !met; ++t)
        met = path_steps::stepsMeet(A, p, t, B, still, 0, model);
    }
    if (met) out.push_back(f);
  }
  return out;
}

}  // namespace fleet_planner
