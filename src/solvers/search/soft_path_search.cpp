#include "fleet_planner/solvers/search/soft_path_search.h"

#include <algorithm>
#include <cmath>
#include <queue>

#include "fleet_planner/solvers/search/space_time_astar.h"
#include "node_table.h"
#include "soft_order.h"

namespace fleet_planner {

namespace {

struct Node {
  StateId s;
  int t;      // time, collapsed into the static layer
  int steps;  // path length so far (the real time)
  int g;      // steps + collision_cost * collisions
  int f;
  int collisions;
  bool finished;  // the agent holds its target from here on; popping it ends the search
  int parent;
};

}  // namespace

SoftSearchResult softPathSearch(const SearchSpace& space, int a, const SoftPathTable& soft,
                                const Deadline& deadline, const SoftSearchOptions& options) {
  SoftSearchResult result;
  const StateGraph& g = space.graph(a);
  const ReservationTable& reservations = space.reservations();
  const StateId start = space.start(a), target = space.target(a);
  if (space.distance(a, start) < 0) return result;
  const GridPose target_pose = g.pose(target);
  const int reserved_last =
      reservations.lastTaken(space.probe(a, target_pose.heading, Action::Wait), {target_pose.x, target_pose.y});
  if (reserved_last == ReservationTable::kForever) return result;
  const int goal_earliest = reserved_last + 1;
  const int static_from = std::max(soft.lastMove(), reservations.lastChange()) + 1;
  const int w = options.collision_cost;

  std::vector<Node> nodes;
  NodeTable seen;
  auto key = [](StateId s, int t, bool finished) {
    return (static_cast<std::uint64_t>(t) << 33) | (static_cast<std::uint64_t>(finished) << 32) |
           static_cast<std::uint32_t>(s);
  };
  std::priority_queue<int, std::vector<int>, SoftOrder<Node>> open(SoftOrder<Node>{&nodes});
  // Lower bound on the rest of the path, weighted (in sixteenths, so that f stays an integer).
  const int weight16 = static_cast<int>(std::lround(std::max(options.heuristic_weight, 1.0) * 16.0));
  auto heuristic = [&](StateId s, int steps) {
    return std::max(space.distance(a, s), goal_earliest - steps) * weight16 / 16;
  };
  auto push = [&](const Node& n) {
    const std::uint64_t k = key(n.s, n.t, n.finished);
    const int* known = seen.find(k);
    if (known != nullptr && nodes[*known].g <= n.g) return;
    seen.set(k, static_cast<int>(nodes.size()));
    nodes.push_back(n);
    open.push(static_cast<int>(nodes.size()) - 1);
  };
  push({start, 0, 0, 0, heuristic(start, 0), 0, false, -1});

  std::vector<int> met;
  while (!open.empty()) {
    if ((result.expansions & 255) == 0 && deadline.expired()) {
      result.outcome = SoftSearchResult::Outcome::Expired;
      return result;
    }
    if (result.expansions >= options.max_expansions) {
      result.outcome = SoftSearchResult::Outcome::NodeLimit;
      return result;
    }
    const int index = open.top();
    open.pop();
    const Node node = nodes[index];
    if (*seen.find(key(node.s, node.t, node.finished)) != index) continue;  // superseded
    ++result.expansions;
    if (node.finished) {
      for (int i = node.parent; i >= 0; i = nodes[i].parent) result.path.push_back(nodes[i].s);
      std::reverse(result.path.begin(), result.path.end());
      result.collisions = node.collisions;
      result.outcome = SoftSearchResult::Outcome::Found;
      return result;
    }
    if (node.s == target && node.steps >= goal_earliest) {
      met.clear();
      soft.collisionsHolding(a, target, node.steps, met);
      const int c = static_cast<int>(met.size());
      push({target, node.t, node.steps, node.g + w * c, node.g + w * c, node.collisions + c, true,
            index});
    }
    const int t_next = std::min(node.t + 1, static_from);
    auto consider = [&](Action act, StateId next) {
      if (space.distance(a, next) < 0 || !space.allows(a, node.s, act)) return;
      const GridPose p = g.pose(node.s);
      if (!reservations.empty() &&
          reservations.taken(space.probe(a, p.heading, act), {p.x, p.y}, node.steps))
        return;
      met.clear();
      soft.collisions(a, node.s, act, node.steps, met);
      const int c = static_cast<int>(met.size());
      const int g_next = node.g + 1 + w * c;
      push({next, t_next, node.steps + 1, g_next, g_next + heuristic(next, node.steps + 1),
            node.collisions + c, false, index});
    };
    consider(Action::Wait, node.s);
    g.forEachSuccessor(node.s, [&](Action act, StateId next) { consider(act, next); });
  }
  return result;
}

}  // namespace fleet_planner
