// Plan refinement; see plan_refinement.h.
#include "fleet_planner/layered/plan_refinement.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "fleet_planner/core/collision.h"
#include "fleet_planner/solvers/agent_constraints.h"
#include "fleet_planner/solvers/la_cbs.h"
#include "fleet_planner/solvers/search_space.h"
#include "fleet_planner/solvers/space_time_astar.h"
#include "path_steps.h"

namespace fleet_planner {

namespace {

using path_steps::radiusOf;

// The robot's path around every other robot's path, strictly cheaper than `cost`; empty if
// there is none (or the search hit a limit).
Path cheaperPath(const Instance& instance, const FleetGraphs& graphs, const std::vector<Path>& paths, int robot,
                 int cost, const Deadline& deadline, const RefinementOptions& options, int& lower_bound,
                 long long& expansions) {
  Subproblem sub;
  sub.instance = &instance;
  sub.graphs = &graphs;
  sub.robots = {robot};
  sub.deadline = deadline;
  // A path of cost below `cost` stays where the Manhattan distances to start and target add up
  // to less than it: robots that never come within reach of that region cannot matter.
  const GridPose& from = instance.robots[robot].start;
  const GridPose& to = instance.robots[robot].target;
  const int radius = radiusOf(graphs.cells(robot));
  for (int j = 0; j < static_cast<int>(paths.size()); ++j) {
    if (j == robot) continue;
    const int slack = cost - 1 + 4 * (radius + radiusOf(graphs.cells(j)));
    const bool near = std::any_of(paths[j].begin(), paths[j].end(), [&](const GridPose& q) {
      return std::abs(q.x - from.x) + std::abs(q.y - from.y) + std::abs(q.x - to.x) + std::abs(q.y - to.y) <= slack;
    });
    if (near) sub.moving.push_back({j, paths[j]});
  }
  const SearchSpace space(sub);
  if (space.stopped() || !space.problem().empty()) return {};  // stopped: the deadline passed
  lower_bound = space.distance(0, space.start(0));
  if (lower_bound >= cost) return {};
  AgentConstraints bound;
  bound.requireCostAtMost(cost - 1);
  LowLevelOptions low;
  low.max_nodes = options.max_nodes_per_search;
  const LowLevelResult found = spaceTimeAStar(space, 0, bound, deadline, low);
  expansions += found.expansions;
  if (found.outcome != LowLevelResult::Outcome::Found) return {};
  Path path;
  for (StateId s : found.path) path.push_back(space.graph(0).pose(s));
  return path;
}

// The robot's cheapest path with nobody else around.
Path idealPath(const Instance& instance, const FleetGraphs& graphs, int robot, const Deadline& deadline) {
  Subproblem sub;
  sub.instance = &instance;
  sub.graphs = &graphs;
  sub.robots = {robot};
  const SearchSpace space(sub);
  if (space.stopped() || !space.problem().empty()) return {};  // stopped: the deadline passed
  const LowLevelResult found = spaceTimeAStar(space, 0, AgentConstraints{}, deadline);
  Path path;
  for (StateId s : found.path) path.push_back(space.graph(0).pose(s));
  return path;
}

// Up to `count` robots whose paths stand in the way of robot i's ideal path: most states whose
// footprint overlaps a footprint of the ideal path first (ties: index).
std::vector<int> blockers(const FleetGraphs& graphs, const std::vector<Path>& paths, int i, const Path& ideal,
                          int count) {
  std::vector<std::pair<int, int>> scored;  // (-score, robot)
  const FootprintCells& A = graphs.cells(i);
  for (int j = 0; j < static_cast<int>(paths.size()); ++j) {
    if (j == i) continue;
    const FootprintCells& B = graphs.cells(j);
    const int reach = radiusOf(A) + radiusOf(B);
    int score = 0;
    for (const GridPose& q : paths[j]) {
      for (const GridPose& p : ideal) {
        if (std::abs(p.x - q.x) > reach || std::abs(p.y - q.y) > reach) continue;
        if (footprintsOverlap(A, p, B, q)) {
          ++score;
          break;
        }
      }
    }
    if (score > 0) scored.push_back({-score, j});
  }
  std::sort(scored.begin(), scored.end());
  std::vector<int> out;
  for (std::size_t k = 0; k < scored.size() && static_cast<int>(k) < count; ++k) out.push_back(scored[k].second);
  return out;
}

}  // namespace

RefinementStats refinePlan(const Instance& instance, const FleetGraphs& graphs, std::vector<Path>& paths,
                           const Deadline& deadline, const RefinementOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  RefinementStats stats;
  const int n = static_cast<int>(paths.size());
  const long long max_expansions = std::min(options.max_expansions, options.expansions_per_robot * n);
  auto costOf = [&](int i) { return pathCost(paths[i], instance.robots[i].target); };
  auto makespan = [&] {
    int m = 0;
    for (int i = 0; i < n; ++i) m = std::max(m, costOf(i));
    return m;
  };
  // Lower bounds, learnt from the searches; until known, a robot's cost stands in for them (so
  // the first pass visits robots by cost).
  std::vector<int> lower(n, 0);
  std::vector<char> known(n, 0);
  std::vector<Path> ideal(n);
  // A search is started only if the longest one so far would still end before the deadline:
  // on hundreds of long paths, building one search's reservation table takes most of a second.
  double longest_search_s = 0.0;
  auto outOfTime = [&] { return deadline.expired() || deadline.remaining() < longest_search_s; };
  auto timed = [&](auto&& search) {
    const auto t = std::chrono::steady_clock::now();
    auto result = search();
    longest_search_s = std::max(longest_search_s, std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count());
    return result;
  };
  auto delayOrder = [&] {
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return costOf(a) - lower[a] > costOf(b) - lower[b]; });
    return order;
  };
  // Robot i and those in the way of its ideal path, replanned together by LA-CBS around the
  // rest; kept when their sum of costs drops.
  auto groupPass = [&] {
    int improved = 0;
    for (int i : delayOrder()) {
      if (outOfTime() || stats.expansions >= max_expansions) break;
      if (!known[i] || costOf(i) <= lower[i]) continue;
      if (ideal[i].empty()) ideal[i] = idealPath(instance, graphs, i, deadline);
      std::vector<int> group = blockers(graphs, paths, i, ideal[i], options.group_size - 1);
      if (group.empty()) continue;
      group.push_back(i);
      std::sort(group.begin(), group.end());
      Subproblem sub;
      sub.instance = &instance;
      sub.graphs = &graphs;
      sub.robots = group;
      sub.deadline = deadline;
      long long before = 0;
      for (int r : group) before += costOf(r);
      for (int j = 0; j < n; ++j) {
        if (!std::binary_search(group.begin(), group.end(), j)) sub.moving.push_back({j, paths[j]});
      }
      LaCbsOptions cbs_options;
      cbs_options.max_high_level_nodes = options.group_nodes;
      cbs_options.pairwise_delay_nodes = 0;
      cbs_options.max_low_level_nodes = options.max_nodes_per_search;
      cbs_options.max_total_expansions = options.group_expansions;
      ++stats.group_searches;
      const SolveResult solved = timed([&] { return LaCbs(cbs_options).solve(sub); });
      stats.expansions += solved.stats.low_level_expansions;
      if (!solved.success()) continue;
      long long after = 0;
      int longest = 0;
      for (std::size_t k = 0; k < group.size(); ++k) {
        const int c = pathCost(solved.paths[k], instance.robots[group[k]].target);
        after += c;
        longest = std::max(longest, c);
      }
      if (after >= before || longest > makespan()) continue;  // SOC drops, makespan does not grow
      for (std::size_t k = 0; k < group.size(); ++k) paths[group[k]] = solved.paths[k];
      stats.soc_saved += before - after;
      ++improved;
    }
    return improved;
  };
  while (stats.passes < options.max_passes && !outOfTime() && stats.expansions < max_expansions) {
    ++stats.passes;
    int improved = 0;
    for (int i : delayOrder()) {
      if (outOfTime() || stats.expansions >= max_expansions) break;
      const int cost = costOf(i);
      if (known[i] && cost <= lower[i]) continue;
      ++stats.searches;
      int bound = lower[i];
      Path better =
          timed([&] { return cheaperPath(instance, graphs, paths, i, cost, deadline, options, bound, stats.expansions); });
      lower[i] = bound;
      known[i] = 1;
      if (better.empty()) continue;
      const int new_cost = pathCost(better, instance.robots[i].target);
      if (new_cost < 0 || new_cost >= cost) continue;
      stats.soc_saved += cost - new_cost;
      paths[i] = std::move(better);
      ++improved;
    }
    stats.improved += improved;
    if (improved > 0) continue;
    if (options.group_size < 2) break;
    const int grouped = groupPass();
    stats.improved += grouped;
    if (grouped == 0) break;
  }
  stats.deadline_hit = outOfTime();
  stats.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace fleet_planner
