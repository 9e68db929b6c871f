#include "fleet_planner/model/fleet_graphs.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <string>
#include <unordered_map>

#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

FleetGraphs::Groups FleetGraphs::group(const std::vector<Footprint>& footprints, int step) {
  // Discretise each distinct footprint once, then group equal cell sets.
  Groups groups;
  std::vector<std::shared_ptr<const FootprintCells>>& distinct = groups.cells;
  std::vector<int>& robot_graph = groups.of_robot;
  std::unordered_multimap<std::size_t, int> by_hash;
  robot_graph.reserve(footprints.size());
  for (std::size_t i = 0; i < footprints.size(); ++i) {
    int found = -1;
    for (std::size_t j = 0; j < i && found < 0; ++j) {
      if (footprints[j] == footprints[i]) found = robot_graph[j];
    }
    if (found < 0) {
      auto cells = sharedFootprintCells(footprints[i], step);
      auto range = by_hash.equal_range(cells->cellsHash());
      for (auto it = range.first; it != range.second && found < 0; ++it) {
        if (distinct[it->second]->sameCells(*cells)) found = it->second;
      }
      if (found < 0) {
        found = static_cast<int>(distinct.size());
        by_hash.emplace(cells->cellsHash(), found);
        distinct.push_back(std::move(cells));
      }
    }
    robot_graph.push_back(found);
  }
  return groups;
}

const GridMap& FleetGraphs::admit(const GridMap& map, const Groups& groups, const ResourceLimits& limits) {
  const int robots = static_cast<int>(groups.of_robot.size());
  checkRobotCount(robots, limits);
  checkMapCells(map.width(), map.height(), limits, map.source().empty() ? std::string("the map") : map.source());
  const MemoryEstimate estimate =
      estimateMemory(map.width(), map.height(), robots, static_cast<int>(groups.cells.size()), 0);
  checkMemory(estimate, residentMemoryMb(), limits, "the state graphs of " + std::to_string(robots) + " robots");
  return map;
}

FleetGraphs::FleetGraphs(const GridMap& map, const std::vector<Footprint>& footprints, ActionModel model,
                         int threads, const ResourceLimits& limits, const Deadline& deadline)
    : FleetGraphs(map, group(footprints, model.step), model, threads, limits, deadline) {}

FleetGraphs::FleetGraphs(const GridMap& map, Groups groups, ActionModel model, int threads,
                         const ResourceLimits& limits, const Deadline& deadline)
    : obstacles_(admit(map, groups, limits)), robot_graph_(std::move(groups.of_robot)) {
  const std::vector<std::shared_ptr<const FootprintCells>>& distinct = groups.cells;
  graphs_.resize(distinct.size());
  std::atomic<std::size_t> next{0};
  std::atomic<bool> expired{false};
  auto worker = [&] {
    for (std::size_t g = next++; g < distinct.size(); g = next++) {
      if (expired || deadline.expired()) {
        expired = true;
        return;
      }
      graphs_[g] = std::make_shared<const StateGraph>(map, obstacles_, distinct[g], model);
    }
  };
  const int n = std::max(1, std::min<int>(threads, static_cast<int>(distinct.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (expired) {
    std::size_t built = 0;
    for (const auto& g : graphs_) built += g ? 1 : 0;
    throw DeadlineExpired("deadline passed while the state graphs were built (" + std::to_string(built) + " of " +
                          std::to_string(distinct.size()) + " built)");
  }
}

FleetGraphs::FleetGraphs(const FleetGraphs& all, const std::vector<int>& robots)
    : obstacles_(all.obstacles_), graphs_(all.graphs_) {
  for (int r : robots) {
    if (r < 0 || r >= all.numRobots()) throw InvalidInput("no robot " + std::to_string(r) + " among the fleet's graphs");
    robot_graph_.push_back(all.robot_graph_[r]);
  }
}

long long FleetGraphs::totalStates() const {
  long long total = 0;
  for (int g : robot_graph_) total += graphs_[g]->numValidStates();
  return total;
}

std::size_t FleetGraphs::memoryBytes() const {
  std::size_t bytes = 0;
  for (const auto& g : graphs_) bytes += g->memoryBytes();
  return bytes;
}

}  // namespace fleet_planner
