#include "fleet_planner/solvers/search/space_time_astar.h"

#include <algorithm>
#include <limits>
#include <memory>

#include "fleet_planner/solvers/search/focal_list.h"
#include "node_table.h"

namespace fleet_planner {

Action stepAction(const StateGraph& graph, StateId from, StateId to) {
  if (from == to) return Action::Wait;
  for (Action a : {Action::Forward, Action::RotateCcw, Action::RotateCw, Action::Backward}) {
    if (graph.next(from, a) == to) return a;
  }
  return Action::Wait;
}

namespace {

// Area constraints stay for good once they start, and from `static_from` nothing changes at
// all. An area may cut the target off or force a long way round, which the plain distance
// cannot tell: a search would fill space-time up to static_from before it gave up. Backward
// searches tell it instead, each a lower bound on the steps left:
// - from `areas_from` (all areas forbidden) on: steps to the target around the areas;
// - before that: steps, ignoring time, into the region from which the target stays reachable
//   around the areas, which must be entered by areas_from;
// - from static_from on: exact steps in the static world (areas and parked obstacles).
class AreaBounds {
 public:
  template <class AroundAreas, class Static>
  AreaBounds(const SearchSpace& space, int a, StateId target, int areas_from, int static_from,
             AroundAreas around_areas, Static static_step)
      : areas_from_(areas_from), static_from_(static_from) {
    const std::vector<StateId> region = backward(space, a, {target}, around_areas, around_areas_);
    backward(space, a, region, [&](StateId p, Action act) { return space.allows(a, p, act); }, to_region_);
    backward(space, a, {target}, static_step, static_);
  }
  /// Node (s, t) can still reach the target.
  bool alive(StateId s, int t) const {
    if (t >= static_from_) return static_[s] >= 0;
    if (t >= areas_from_) return around_areas_[s] >= 0;
    return to_region_[s] >= 0 && t + to_region_[s] <= areas_from_;
  }
  /// Steps left from s at time t, at least (s alive).
  int atLeast(StateId s, int t, int distance) const {
    if (t >= static_from_) return static_[s];
    return t >= areas_from_ ? around_areas_[s] : distance;
  }

 private:
  // Breadth-first over edges `allowed(p, action)` into the states reached, from `sources`;
  // returns the states reached.
  template <class Allowed>
  static std::vector<StateId> backward(const SearchSpace& space, int a, const std::vector<StateId>& sources,
                                       Allowed allowed, std::vector<std::int32_t>& steps) {
    const StateGraph& g = space.graph(a);
    steps.assign(static_cast<std::size_t>(g.stateIdCount()), -1);
    std::vector<StateId> queue = sources;
    for (StateId s : sources) steps[s] = 0;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const StateId s = queue[head];
      g.forEachPredecessor(s, [&](Action act, StateId p) {
        if (steps[p] >= 0 || space.distance(a, p) < 0 || !allowed(p, act)) return;
        steps[p] = steps[s] + 1;
        queue.push_back(p);
      });
    }
    return queue;
  }

  int areas_from_, static_from_;
  std::vector<std::int32_t> around_areas_, to_region_, static_;
};

struct Node {
  StateId s;
  int t;              // collapsed time
  bool held;          // reached by waiting at the target: its cost is an earlier arrival's
  int g;
  int f;
  int conflicts;
  int parent;
};

// The orders of the open list. Weight 1: best-first by f, then fewer conflicts, deeper, first
// generated. Weight w > 1 (focal search): among the nodes whose f is at most w times the least
// open f, fewest conflicts first, then as above.
struct ByF {
  const std::vector<Node>* nodes;
  bool operator()(int x, int y) const {
    const Node &a = (*nodes)[x], &b = (*nodes)[y];
    if (a.f != b.f) return a.f > b.f;
    if (a.conflicts != b.conflicts) return a.conflicts > b.conflicts;
    if (a.g != b.g) return a.g < b.g;  // deeper first
    return x > y;                      // then first generated: deterministic
  }
};
struct ByConflicts {
  const std::vector<Node>* nodes;
  bool operator()(int x, int y) const {
    const Node &a = (*nodes)[x], &b = (*nodes)[y];
    if (a.conflicts != b.conflicts) return a.conflicts > b.conflicts;
    return ByF{nodes}(x, y);
  }
};
struct NodeF {
  int operator()(const Node& n) const { return n.f; }
};
using Focal = FocalList<Node, ByF, ByConflicts, NodeF>;

// The open list. At weight 1 a heap per f value of the order's keys, copied out of the nodes: a
// comparison reads the heap's own entries instead of two nodes at random places of the node
// vector, and a push or pop sifts only among the nodes of its f (the heap's sifting was a
// quarter of a constraint tree's time). The order is ByF's, a total order, so the nodes come
// out as from FocalList.
class Frontier {
 public:
  Frontier(const std::vector<Node>& nodes, double weight) : nodes_(nodes), weight_(weight), focal_(nodes, weight) {}

  void push(int i) {
    if (weight_ > 1.0) return focal_.push(i);
    const Node& n = nodes_[i];
    if (buckets_.empty()) base_ = n.f;
    if (n.f < base_) {  // below every f so far (not with a consistent heuristic): room in front
      buckets_.insert(buckets_.begin(), static_cast<std::size_t>(base_ - n.f), {});
      base_ = n.f;
    }
    const auto k = static_cast<std::size_t>(n.f - base_);
    if (k >= buckets_.size()) buckets_.resize(k + 1);
    buckets_[k].push_back({n.conflicts, n.g, i});
    std::push_heap(buckets_[k].begin(), buckets_[k].end(), Worse{});
    lowest_ = std::min(lowest_, k);
    ++size_;
  }
  /// The next node, or -1; `dead` as FocalList::pop (at weight 1 the caller skips those).
  template <class Dead>
  int pop(Dead dead) {
    if (weight_ > 1.0) return focal_.pop(dead);
    if (size_ == 0) return -1;
    while (buckets_[lowest_].empty()) ++lowest_;
    least_f_ = base_ + static_cast<int>(lowest_);
    std::vector<Entry>& bucket = buckets_[lowest_];
    std::pop_heap(bucket.begin(), bucket.end(), Worse{});
    const int index = bucket.back().index;
    bucket.pop_back();
    --size_;
    return index;
  }
  long long leastF() const { return weight_ > 1.0 ? focal_.leastF() : least_f_; }

 private:
  struct Entry {
    int conflicts, g, index;
  };
  struct Worse {  // ByF on the copied keys, among nodes of one f
    bool operator()(const Entry& a, const Entry& b) const {
      if (a.conflicts != b.conflicts) return a.conflicts > b.conflicts;
      if (a.g != b.g) return a.g < b.g;
      return a.index > b.index;
    }
  };
  const std::vector<Node>& nodes_;
  double weight_;
  Focal focal_;
  std::vector<std::vector<Entry>> buckets_;  // by f - base_
  int base_ = 0;                             // the least f pushed
  std::size_t lowest_ = std::numeric_limits<std::size_t>::max();  // no bucket below holds a node
  std::size_t size_ = 0;
  int least_f_ = 0;  // f of the last node popped
};

}  // namespace

LowLevelResult spaceTimeAStar(const SearchSpace& space, int a, const AgentConstraints& constraints,
                              const Deadline& deadline, const LowLevelOptions& options) {
  LowLevelResult result;
  const StateGraph& g = space.graph(a);
  const FootprintCells& cells = space.cells(a);
  const ReservationTable& reservations = space.reservations();
  const StateId start = space.start(a), target = space.target(a);
  if (space.distance(a, start) < 0) return result;

  // Earliest time from which the agent can stay at its target forever.
  const GridPose target_pose = g.pose(target);
  const int reserved_last = reservations.lastTaken(space.probe(a, target_pose.heading, Action::Wait), {target_pose.x, target_pose.y});
  if (reserved_last == ReservationTable::kForever) return result;
  const int target_blocked = constraints.lastBlockedAt(cells, target_pose);
  if (target_blocked == AgentConstraints::kForever) return result;
  const int goal_earliest = std::max({target_blocked + 1, reserved_last + 1, constraints.minCost()});
  const int max_cost = constraints.maxCost();
  if (goal_earliest > max_cost) return result;
  const int static_from = std::max({constraints.maxTime(), reservations.lastChange(), options.blocked_until}) + 1;

  auto stepBlocked = [&](StateId s, Action act, int t) {
    const GridPose p = g.pose(s);
    if (constraints.stepForbidden(cells, p, act, t)) return true;
    if (options.blocked && options.blocked(s, act, t)) return true;
    return !reservations.empty() && reservations.taken(space.probe(a, p.heading, act), {p.x, p.y}, t);
  };

  std::vector<Node> nodes;
  NodeTable seen;
  // A path's cost is its last arrival at the target, so a node reached by waiting there is kept
  // apart from one that arrives (and only an arrival ends the search): this makes a lower bound
  // on the cost exact (Li et al. 2020's wait_at_goal).
  auto key = [](StateId s, int t, bool held) {
    return (static_cast<std::uint64_t>(t) << 33) | (static_cast<std::uint64_t>(held) << 32) |
           static_cast<std::uint32_t>(s);
  };
  Frontier open(nodes, options.focal_weight);
  auto superseded = [&](int i) {
    const Node& n = nodes[i];
    return *seen.find(key(n.s, n.t, n.held)) != i;
  };

  if (constraints.poseForbidden(cells, g.pose(start), 0)) return result;
  // Heuristic: the distance, but never less than the time left until the target can be held
  // (admissible and consistent: it drops by at most one per step).
  std::unique_ptr<AreaBounds> bounds;
  auto heuristic = [&](StateId s, int t) {
    const int d = bounds ? bounds->atLeast(s, t, space.distance(a, s)) : space.distance(a, s);
    return std::max(d, goal_earliest - t);
  };
  nodes.push_back({start, 0, false, 0, heuristic(start, 0), 0, -1});
  seen.set(key(start, 0, false), 0);
  open.push(0);

  for (;;) {
    if ((result.expansions & 255) == 0 && deadline.expired()) {
      result.outcome = LowLevelResult::Outcome::Expired;
      return result;
    }
    const int index = open.pop(superseded);
    if (index < 0) break;
    const Node node = nodes[index];
    if (superseded(index)) continue;  // by a cheaper duplicate
    if (bounds && !bounds->alive(node.s, node.g)) continue;
    ++result.expansions;
    if (!bounds && constraints.hasAreas() && result.expansions > options.area_bounds_after) {
      // A time past every time constraint: only the areas speak there.
      const int late = AgentConstraints::kForever - 1;
      auto around_areas = [&](StateId p, Action act) {
        return space.allows(a, p, act) && !constraints.poseForbidden(cells, g.pose(p), late) &&
               !constraints.stepForbidden(cells, g.pose(p), act, late);
      };
      auto static_step = [&](StateId p, Action act) {
        const GridPose pose = g.pose(p);
        if (constraints.poseForbidden(cells, pose, static_from)) return false;
        if (!reservations.empty() && reservations.taken(space.probe(a, pose.heading, Action::Wait), {pose.x, pose.y}, static_from))
          return false;
        return space.allows(a, p, act) && !stepBlocked(p, act, static_from);
      };
      bounds = std::make_unique<AreaBounds>(space, a, target, constraints.areasFrom(), static_from, around_areas,
                                            static_step);
      if (!bounds->alive(node.s, node.g)) continue;
    }
    if (node.s == target && !node.held && node.g >= goal_earliest) {
      for (int i = index; i >= 0; i = nodes[i].parent) result.path.push_back(nodes[i].s);
      std::reverse(result.path.begin(), result.path.end());
      result.lower_bound = static_cast<int>(std::min<long long>(node.g, open.leastF()));
      result.outcome = LowLevelResult::Outcome::Found;
      return result;
    }
    const int t_next = std::min(node.t + 1, static_from);
    auto consider = [&](Action act, StateId next) {
      if (space.distance(a, next) < 0) return;
      if (bounds && !bounds->alive(next, node.g + 1)) return;
      const int h = heuristic(next, node.g + 1);
      if (node.g + 1 + h > max_cost) return;  // f bounds the cost from below
      if (!space.allows(a, node.s, act)) return;
      if (constraints.poseForbidden(cells, g.pose(next), node.g + 1) || stepBlocked(node.s, act, node.g)) return;
      // Below the static layer time equals g, so a duplicate is never cheaper; in it, it can be.
      const bool held = act == Action::Wait && next == target;
      const std::uint64_t k = key(next, t_next, held);
      const int* known = seen.find(k);
      if (known != nullptr && nodes[*known].g <= node.g + 1) return;
      const int c = options.conflicts ? node.conflicts + options.conflicts(node.s, act, node.g) : 0;
      seen.set(k, static_cast<int>(nodes.size()));
      nodes.push_back({next, t_next, held, node.g + 1, node.g + 1 + h, c, index});
      open.push(static_cast<int>(nodes.size()) - 1);
    };
    consider(Action::Wait, node.s);
    g.forEachSuccessor(node.s, [&](Action act, StateId next) { consider(act, next); });
    if (static_cast<long long>(nodes.size()) > options.max_nodes) {
      result.outcome = LowLevelResult::Outcome::NodeLimit;
      return result;
    }
  }
  return result;
}

}  // namespace fleet_planner
