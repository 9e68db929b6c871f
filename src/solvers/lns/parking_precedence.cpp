// Which robots must park before which; see parking_precedence.h.
#include "fleet_planner/solvers/lns/parking_precedence.h"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <functional>
#include <queue>
#include <tuple>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/solvers/lns/parking_orders.h"

namespace fleet_planner {

namespace {

// The two searches of wayAroundTarget over one graph's state ids, their marks kept between
// calls and cleared where the last call wrote.
class AroundSearch {
 public:
  WayAround run(const SearchSpace& space, int a, int b, long long max_expansions) {
    const StateGraph& g = space.graph(a);
    if (static_cast<int>(seen_.size()) < g.stateIdCount()) seen_.assign(g.stateIdCount(), 0);
    for (StateId s : touched_) seen_[s] = 0;
    touched_.clear();
    const GridPose q = space.graph(b).pose(space.target(b));
    const int reach = space.cells(a).reach() + space.cells(b).reach();
    auto blocked = [&](StateId s) {
      const GridPose p = g.pose(s);
      return !fartherApart(p, q, reach) && footprintsOverlap(space.cells(b), q, space.cells(a), p);
    };
    const StateId from = space.start(a);
    const StateId to = space.target(a);
    // A pair that overlaps at an end is not a matter of who parks first.
    if (space.distance(a, from) < 0 || blocked(from) || blocked(to)) return WayAround::Unknown;
    if (from == to) return WayAround::Open;

    // Forward: A* by a's distances (exact without b, so it follows a's way and goes round b);
    // each state is entered once (only whether the target is reached matters).
    using Entry = std::tuple<int, int, StateId>;  // f, -g, state
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> ahead;
    std::deque<StateId> back;
    mark(from, kFromStart);
    ahead.push({space.distance(a, from), 0, from});
    mark(to, kFromTarget);
    back.push_back(to);
    for (long long spent = 0; spent < max_expansions; spent += 2) {
      if (ahead.empty() || back.empty()) return WayAround::Closed;
      const auto [f, neg_g, s] = ahead.top();
      ahead.pop();
      bool met = false;
      space.graph(a).forEachSuccessor(s, [&](Action action, StateId t) {
        if (met || (seen_[t] & (kFromStart | kBlocked))) return;
        if (!space.allows(a, s, action) || space.distance(a, t) < 0) return;
        if (seen_[t] & kFromTarget) {
          met = true;
          return;
        }
        if (blocked(t)) return mark(t, kBlocked);
        mark(t, kFromStart);
        ahead.push({1 - neg_g + space.distance(a, t), neg_g - 1, t});
      });
      if (met) return WayAround::Open;
      const StateId u = back.front();
      back.pop_front();
      g.forEachPredecessor(u, [&](Action action, StateId t) {
        if (met || (seen_[t] & (kFromTarget | kBlocked)) || !space.allows(a, t, action)) return;
        if (seen_[t] & kFromStart) {
          met = true;
          return;
        }
        if (blocked(t)) return mark(t, kBlocked);
        mark(t, kFromTarget);
        back.push_back(t);
      });
      if (met) return WayAround::Open;
    }
    return WayAround::Unknown;
  }

 private:
  static constexpr std::uint8_t kFromStart = 1, kFromTarget = 2, kBlocked = 4;
  void mark(StateId s, std::uint8_t bit) {
    if (seen_[s] == 0) touched_.push_back(s);
    seen_[s] |= bit;
  }
  std::vector<std::uint8_t> seen_;
  std::vector<StateId> touched_;
};

}  // namespace

WayAround wayAroundTarget(const SearchSpace& space, int a, int b, long long max_expansions) {
  AroundSearch search;
  return search.run(space, a, b, max_expansions);
}

std::vector<std::vector<int>> parkingPrecedence(const SearchSpace& space, const std::vector<StatePath>& ways,
                                                long long max_expansions_per_pair) {
  const int n = space.numAgents();
  std::vector<std::vector<int>> before(n);
  AroundSearch search;
  for (int a = 0; a < n; ++a) {
    if (ways[a].empty()) continue;
    // The way's bounding box: targets farther from it than the two reaches cannot touch it.
    int x0 = space.graph(a).width(), y0 = space.graph(a).height(), x1 = -1, y1 = -1;
    for (StateId s : ways[a]) {
      const GridPose p = space.graph(a).pose(s);
      x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
    }
    for (int b = 0; b < n; ++b) {
      if (b == a) continue;
      const GridPose target = space.graph(b).pose(space.target(b));
      const int reach = space.cells(a).reach() + space.cells(b).reach();
      if (target.x < x0 - reach || target.x > x1 + reach || target.y < y0 - reach || target.y > y1 + reach) continue;
      if (!wayCoversTarget(space, a, ways[a], b)) continue;
      if (search.run(space, a, b, max_expansions_per_pair) == WayAround::Closed) before[b].push_back(a);
    }
  }
  return before;
}

std::vector<int> honourPrecedence(const std::vector<int>& order, const std::vector<std::vector<int>>& before) {
  const int n = static_cast<int>(before.size());
  std::vector<int> position(n, -1);
  for (int i = 0; i < static_cast<int>(order.size()); ++i) position[order[i]] = i;
  std::vector<int> waiting(n, 0);          // before-agents in the order not yet placed
  std::vector<std::vector<int>> after(n);  // agents waiting for each
  for (int b : order) {
    for (int a : before[b]) {
      if (position[a] < 0) continue;
      ++waiting[b];
      after[a].push_back(b);
    }
  }
  std::priority_queue<int, std::vector<int>, std::greater<int>> ready;  // positions
  for (int b : order) {
    if (waiting[b] == 0) ready.push(position[b]);
  }
  std::vector<char> placed(n, 0);
  std::vector<int> result;
  result.reserve(order.size());
  std::size_t next_left = 0;  // the earliest position that may still be unplaced
  while (result.size() < order.size()) {
    int agent = -1;
    while (!ready.empty() && agent < 0) {
      const int candidate = order[ready.top()];
      ready.pop();
      if (!placed[candidate]) agent = candidate;
    }
    if (agent < 0) {  // a cycle: the earliest agent left goes
      while (placed[order[next_left]]) ++next_left;
      agent = order[next_left];
    }
    placed[agent] = 1;
    result.push_back(agent);
    for (int b : after[agent]) {
      if (--waiting[b] == 0 && !placed[b]) ready.push(position[b]);
    }
  }
  return result;
}

}  // namespace fleet_planner
