#include "fleet_planner/solvers/search/joint_path_search.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <queue>

#include "fleet_planner/runtime/errors.h"
#include "joint_node_table.h"
#include "soft_order.h"

namespace fleet_planner {

namespace {

using Joint = std::array<StateId, kMaxJointGroup>;

struct Node {
  Joint s;
  int t;      // time, collapsed into the static layer
  int steps;  // the real time
  int g;      // member-steps before committing + collision_cost * collisions
  int f;
  int collisions;
  unsigned done;  // members that hold their targets from here on (bit i: member i)
  int parent;
};

// A node's key: its members' states, its (collapsed) time and the members done.
bool sameKey(const Node& a, const Node& b) { return a.s == b.s && a.t == b.t && a.done == b.done; }

std::uint64_t keyHash(const Node& k) {
  std::uint64_t h = (static_cast<std::uint64_t>(k.t) << kMaxJointGroup) + k.done;
  for (StateId s : k.s) h = (h ^ static_cast<std::uint32_t>(s)) * 0x9e3779b97f4a7c15ULL;
  return h ^ (h >> 29);
}

// One member's move during a step: the action, where it leads, and what it sweeps.
struct Move {
  Action action;
  StateId next;
  const CellSet* swept;
  Cell origin;
  int collisions;  // agents outside the group met during the step
  int cost;        // 0 for a member committed to its target, else 1
};

}  // namespace

JointSearchResult jointPathSearch(const SearchSpace& space, const std::vector<int>& group,
                                  const SoftPathTable& soft, const Deadline& deadline,
                                  const JointSearchOptions& options) {
  const int n = static_cast<int>(group.size());
  if (n < 1 || n > kMaxJointGroup)
    throw InvalidInput("joint path search: a group of " + std::to_string(n) + " agents (1 to " +
                       std::to_string(kMaxJointGroup) + " allowed)");
  if (!options.from.empty() && static_cast<int>(options.from.size()) != n)
    throw InvalidInput("joint path search: " + std::to_string(options.from.size()) + " states to start from for " +
                       std::to_string(n) + " agents");
  const int t0 = std::max(0, options.from_step);
  JointSearchResult result;
  const ReservationTable& reservations = space.reservations();
  std::array<int, kMaxJointGroup> goal_earliest{};
  Joint start{}, target{};
  for (int i = 0; i < n; ++i) {
    const int a = group[i];
    start[i] = options.from.empty() ? space.start(a) : options.from[i];
    target[i] = space.target(a);
    if (space.distance(a, start[i]) < 0) return result;
    const GridPose p = space.graph(a).pose(target[i]);
    const int last = reservations.lastTaken(space.probe(a, p.heading, Action::Wait), {p.x, p.y});
    if (last == ReservationTable::kForever) return result;
    goal_earliest[i] = last + 1;
  }
  const int exact_static_from = std::max(soft.lastMove(), reservations.lastChange()) + 1;
  const int static_from = options.static_from >= 0 ? std::min(exact_static_from, options.static_from)
                                                   : exact_static_from;
  const int w = options.collision_cost;

  const unsigned all = (1u << n) - 1;
  std::vector<Node> nodes;
  std::vector<char> superseded;  // per node: a cheaper node with its key came later
  JointNodeTable seen;
  std::priority_queue<int, std::vector<int>, SoftOrder<Node>> open(SoftOrder<Node>{&nodes});
  auto heuristic = [&](const Joint& s, unsigned done) {
    int h = 0;
    for (int i = 0; i < n; ++i) h += (done >> i & 1u) ? 0 : space.distance(group[i], s[i]);
    return h;
  };
  auto push = [&](Node node) {
    node.f = node.g + heuristic(node.s, node.done);
    bool added = false;
    int& entry = seen.entry(keyHash(node), [&](int j) { return sameKey(nodes[j], node); }, added);
    if (!added) {
      if (nodes[entry].g <= node.g) return;
      superseded[entry] = 1;
    }
    entry = static_cast<int>(nodes.size());
    nodes.push_back(node);
    superseded.push_back(0);
    open.push(static_cast<int>(nodes.size()) - 1);
  };
  push({start, std::min(t0, static_from), t0, 0, 0, 0, 0u, -1});

  std::vector<int> met;
  std::array<std::vector<Move>, kMaxJointGroup> moves;
  std::array<int, kMaxJointGroup> pick{};
  while (!open.empty()) {
    if ((result.expansions & 255) == 0 && deadline.expired()) {
      result.outcome = JointSearchResult::Outcome::Expired;
      return result;
    }
    if (static_cast<long long>(nodes.size()) >= options.max_nodes) {
      result.outcome = JointSearchResult::Outcome::NodeLimit;
      return result;
    }
    const int index = open.top();
    open.pop();
    const Node node = nodes[index];
    if (superseded[index]) continue;
    ++result.expansions;
    if (node.done == all) {
      std::vector<int> chain;
      for (int j = index; j >= 0; j = nodes[j].parent) chain.push_back(j);
      std::reverse(chain.begin(), chain.end());
      for (int i = 0; i < n; ++i) {
        // Member i's states until it committed to its target (commits take no time).
        StatePath& path = result.paths.emplace_back();
        for (int j : chain) {
          if (nodes[j].steps - t0 == static_cast<int>(path.size())) path.push_back(nodes[j].s[i]);
          if (nodes[j].done >> i & 1u) break;
        }
      }
      result.collisions = node.collisions;
      result.outcome = JointSearchResult::Outcome::Found;
      return result;
    }
    // Members at their targets may commit to stay there (no time passes); the agents outside
    // the group they would meet while standing there are charged now.
    for (int i = 0; i < n; ++i) {
      if ((node.done >> i & 1u) || node.s[i] != target[i] || node.steps < goal_earliest[i]) continue;
      met.clear();
      soft.collisionsHolding(group[i], target[i], node.steps, met);
      const int c = static_cast<int>(met.size());
      Node next = node;
      next.done |= 1u << i;
      next.g += w * c;
      next.collisions += c;
      next.parent = index;
      push(next);
    }
    // Each member's possible moves on its own, then every combination that keeps them apart.
    bool stuck = false;
    for (int i = 0; i < n && !stuck; ++i) {
      const int a = group[i];
      const StateGraph& g = space.graph(a);
      const FootprintCells& cells = space.cells(a);
      const StateId s = node.s[i];
      const GridPose p = g.pose(s);
      moves[i].clear();
      if (node.done >> i & 1u) {
        moves[i].push_back({Action::Wait, s, &cells.swept(p.heading, Action::Wait), {p.x, p.y}, 0, 0});
        continue;
      }
      auto consider = [&](Action act, StateId next) {
        if (space.distance(a, next) < 0 || !space.allows(a, s, act)) return;
        const CellSet& swept = cells.swept(p.heading, act);
        if (!reservations.empty() && reservations.taken(space.probe(a, p.heading, act), {p.x, p.y}, node.steps)) return;
        met.clear();
        soft.collisions(a, s, act, node.steps, met);
        moves[i].push_back({act, next, &swept, {p.x, p.y}, static_cast<int>(met.size()), 1});
      };
      consider(Action::Wait, s);
      g.forEachSuccessor(s, [&](Action act, StateId next) { consider(act, next); });
      stuck = moves[i].empty();
    }
    if (stuck) continue;
    const int t_next = std::min(node.t + 1, static_from);
    // Odometer over the members' moves; combinations in which two sweep a common cell are skipped.
    pick.fill(0);
    while (true) {
      bool apart = true;
      for (int i = 0; i < n && apart; ++i) {
        for (int j = i + 1; j < n && apart; ++j) {
          const Move &x = moves[i][pick[i]], &y = moves[j][pick[j]];
          apart = !CellSet::overlap(*x.swept, x.origin, *y.swept, y.origin);
        }
      }
      if (apart) {
        Node next{node.s, t_next, node.steps + 1, node.g, 0, node.collisions, node.done, index};
        for (int i = 0; i < n; ++i) {
          const Move& m = moves[i][pick[i]];
          next.s[i] = m.next;
          next.g += m.cost + w * m.collisions;
          next.collisions += m.collisions;
        }
        push(next);
      }
      int i = 0;
      while (i < n && ++pick[i] == static_cast<int>(moves[i].size())) pick[i++] = 0;
      if (i == n) break;
    }
  }
  return result;
}

}  // namespace fleet_planner
