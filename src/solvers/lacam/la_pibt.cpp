#include "fleet_planner/solvers/lacam/la_pibt.h"

#include <algorithm>
#include <unordered_set>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/solvers/search/space_time_astar.h"

namespace fleet_planner {

LaPibt::LaPibt(const SearchSpace& space, std::uint64_t seed)
    : space_(space),
      rng_(seed),
      reach_(space.numAgents()),
      stamp_(space.numAgents(), 0),
      chosen_(space.numAgents()),
      assigned_(space.numAgents()) {
  if (space.numAgents() == 0) return;
  bx_ = (space.graph(0).width() + kBucketCells - 1) / kBucketCells;
  by_ = (space.graph(0).height() + kBucketCells - 1) / kBucketCells;
  near_.resize(static_cast<std::size_t>(bx_) * by_);
  for (int a = 0; a < space.numAgents(); ++a) {
    int r = 0;
    while (r * r < space.cells(a).maxNormSq()) ++r;
    reach_[a] = r;
  }
}

void LaPibt::indexNear(const Config& current) {
  for (int bucket : filled_) near_[bucket].clear();
  filled_.clear();
  for (int b = 0; b < space_.numAgents(); ++b) {
    const GridPose q = space_.graph(b).pose(current[b]);
    const int r = reach_[b];
    for (int y = bucketY(q.y - r); y <= bucketY(q.y + r); ++y) {
      for (int x = bucketX(q.x - r); x <= bucketX(q.x + r); ++x) {
        std::vector<int>& agents = near_[y * bx_ + x];
        if (agents.empty()) filled_.push_back(y * bx_ + x);
        agents.push_back(b);
      }
    }
  }
}

template <class F>
void LaPibt::forNear(int a, const CellSet& set, Cell origin, F&& f) const {
  if (set.empty()) return;
  if (++query_ == 0) {  // wrapped: forget every stamp
    std::fill(stamp_.begin(), stamp_.end(), 0);
    query_ = 1;
  }
  stamp_[a] = query_;
  for (int y = bucketY(origin.y + set.minY()); y <= bucketY(origin.y + set.maxY()); ++y) {
    for (int x = bucketX(origin.x + set.minX()); x <= bucketX(origin.x + set.maxX()); ++x) {
      for (int b : near_[y * bx_ + x]) {
        if (stamp_[b] == query_) continue;
        stamp_[b] = query_;
        f(b);
      }
    }
  }
}

std::vector<StateId> LaPibt::candidates(int a, StateId s) const {
  std::vector<StateId> out{s};
  space_.graph(a).forEachSuccessor(s, [&](Action action, StateId next) {
    if (space_.distance(a, next) >= 0 && space_.allows(a, s, action)) out.push_back(next);
  });
  return out;
}

bool LaPibt::fits(int a, StateId from, Action action, const Config& current) const {
  const GridPose p = space_.graph(a).pose(from);
  const FootprintCells& cells = space_.cells(a);
  bool clear = true;
  forNear(a, cells.swept(p.heading, action), {p.x, p.y}, [&](int b) {
    if (!clear) return;
    const GridPose q = space_.graph(b).pose(current[b]);
    // An agent still to move sweeps at least its current footprint, whatever it does.
    const Action other = assigned_[b] ? chosen_[b] : Action::Wait;
    if (sweepsOverlap(cells, p, action, space_.cells(b), q, other)) clear = false;
  });
  return clear;
}

std::vector<int> LaPibt::blockers(int a, StateId from, Action action, const Config& current) const {
  std::vector<int> out;
  const GridPose p = space_.graph(a).pose(from);
  forNear(a, space_.cells(a).swept(p.heading, action), {p.x, p.y}, [&](int b) {
    if (assigned_[b]) return;
    if (sweepsOverlap(space_.cells(a), p, action, space_.cells(b), space_.graph(b).pose(current[b]), Action::Wait)) {
      out.push_back(b);
    }
  });
  std::sort(out.begin(), out.end());  // agent order, whatever the buckets' order
  return out;
}

std::vector<int> LaPibt::escapeSteps(int a, StateId from, const CellSet& sweep, Cell origin) const {
  // Breadth-first from `from` in a's own graph (other agents ignored), remembering each state's
  // first step; the depth at which a first step first reaches a state clear of the sweep ranks it.
  const StateGraph& g = space_.graph(a);
  auto clear = [&](StateId s) {
    const GridPose p = g.pose(s);
    return !CellSet::overlap(space_.cells(a).body(p.heading), {p.x, p.y}, sweep, origin);
  };
  std::vector<StateId> firsts;
  std::vector<int> depth_of_first;
  struct Item {
    StateId s;
    int first;
    int depth;
  };
  std::vector<Item> queue;
  std::unordered_set<StateId> seen{from};
  g.forEachSuccessor(from, [&](Action action, StateId next) {
    if (!space_.allows(a, from, action)) return;
    firsts.push_back(next);
    depth_of_first.push_back(-1);
    queue.push_back({next, static_cast<int>(firsts.size()) - 1, 1});
    seen.insert(next);
  });
  int found_depth = -1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const Item item = queue[head];
    if (found_depth >= 0 && item.depth > found_depth + 1) break;
    if (depth_of_first[item.first] < 0 && clear(item.s)) {
      depth_of_first[item.first] = item.depth;
      if (found_depth < 0) found_depth = item.depth;
    }
    if (item.depth >= kEscapeDepth || queue.size() >= kEscapeStates) continue;
    g.forEachSuccessor(item.s, [&](Action action, StateId next) {
      if (!space_.allows(a, item.s, action) || !seen.insert(next).second) return;
      queue.push_back({next, item.first, item.depth + 1});
    });
  }
  std::vector<int> order;
  for (std::size_t k = 0; k < firsts.size(); ++k) {
    if (depth_of_first[k] >= 0) order.push_back(static_cast<int>(k));
  }
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return depth_of_first[x] < depth_of_first[y]; });
  std::vector<int> result;
  for (int k : order) result.push_back(firsts[k]);
  return result;
}

bool LaPibt::assign(int a, const Config& current, Config& next, int pusher, StateId avoid) {
  assigned_[a] = true;
  chosen_[a] = Action::Wait;  // while deciding, a counts as waiting for the others
  next[a] = current[a];
  std::vector<StateId> options;
  if (pusher >= 0) {
    // Pushed: step towards the nearest state clear of the cells the pusher will sweep next
    // step. Large robots without reverse often need a turn first, so progress is enough.
    const GridPose from = space_.graph(pusher).pose(current[pusher]);
    const Action action = stepAction(space_.graph(pusher), current[pusher], avoid);
    options = escapeSteps(a, current[a], space_.cells(pusher).swept(from.heading, action), {from.x, from.y});
  } else {
    // Best first by distance to the target; random tie-break from the seed.
    options = candidates(a, current[a]);
    std::vector<std::pair<StateId, std::uint64_t>> ranked;
    for (StateId s : options) ranked.push_back({s, rng_.next()});
    std::sort(ranked.begin(), ranked.end(), [&](const auto& x, const auto& y) {
      const int dx = space_.distance(a, x.first), dy = space_.distance(a, y.first);
      return dx != dy ? dx < dy : x.second < y.second;
    });
    options.clear();
    for (const auto& r : ranked) options.push_back(r.first);
  }
  for (const StateId s : options) {
    if (s == current[a]) return pusher < 0;  // waiting is the best it can do
    const Action action = stepAction(space_.graph(a), current[a], s);
    if (fits(a, current[a], action, current)) {
      next[a] = s;
      chosen_[a] = action;
      return true;
    }
    // Blocked: if only agents still to move are in the way, ask them to clear, and wait.
    const std::vector<int> in_way = blockers(a, current[a], action, current);
    if (in_way.empty()) continue;
    bool cleared = true;
    for (int b : in_way) {
      if (!assigned_[b]) cleared = assign(b, current, next, a, s) && cleared;
    }
    if (cleared) return pusher < 0;  // a waits; the way to s opens next step
  }
  return pusher < 0;
}

bool LaPibt::generate(const Config& current, const std::vector<std::pair<int, StateId>>& fixed,
                      const std::vector<int>& order, Config& next) {
  const int n = space_.numAgents();
  next.assign(n, kNoState);
  std::fill(assigned_.begin(), assigned_.end(), false);
  indexNear(current);
  for (const auto& [a, s] : fixed) {
    const Action action = stepAction(space_.graph(a), current[a], s);
    if (assigned_[a] || !fits(a, current[a], action, current)) return false;
    next[a] = s;
    chosen_[a] = action;
    assigned_[a] = true;
  }
  for (int a : order) {
    if (!assigned_[a]) assign(a, current, next, -1, kNoState);
  }
  return true;
}

}  // namespace fleet_planner
