#include "fleet_planner/solvers/lacam/la_pibt.h"

#include <algorithm>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/solvers/search/space_time_astar.h"

namespace fleet_planner {

namespace {

// Stable sort of the first n (at most kActions) entries of `items`.
template <class Array, class Less>
void sortFew(Array& items, int n, Less less) {
  for (int i = 1; i < n; ++i) {
    for (int j = i; j > 0 && less(items[j], items[j - 1]); --j) std::swap(items[j], items[j - 1]);
  }
}

}  // namespace

LaPibt::LaPibt(const SearchSpace& space, std::uint64_t seed, bool remember_escapes)
    : space_(space),
      rng_(seed),
      reach_(space.numAgents()),
      stamp_(space.numAgents(), 0),
      chosen_(space.numAgents()),
      assigned_(space.numAgents()),
      remember_escapes_(remember_escapes) {
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

StateChoices LaPibt::candidates(int a, StateId s) const {
  StateChoices out;
  out.push(s);
  space_.graph(a).forEachSuccessor(s, [&](Action action, StateId next) {
    if (space_.distance(a, next) >= 0 && space_.allows(a, s, action)) out.push(next);
  });
  return out;
}

bool LaPibt::fits(int a, StateId from, Action action, const Config& current, std::vector<int>* in_way) const {
  const GridPose p = space_.graph(a).pose(from);
  const FootprintCells& cells = space_.cells(a);
  bool clear = true;
  forNear(a, cells.swept(p.heading, action), {p.x, p.y}, [&](int b) {
    if (!clear && (in_way == nullptr || assigned_[b])) return;
    const GridPose q = space_.graph(b).pose(current[b]);
    // An agent still to move sweeps at least its current footprint, whatever it does.
    const Action other = assigned_[b] ? chosen_[b] : Action::Wait;
    if (!sweepsOverlap(cells, p, action, space_.cells(b), q, other)) return;
    clear = false;
    if (in_way != nullptr && !assigned_[b]) in_way->push_back(b);
  });
  if (in_way != nullptr) std::sort(in_way->begin(), in_way->end());  // agent order, whatever the buckets' order
  return clear;
}

StateChoices LaPibt::escapeSteps(int a, StateId from, const CellSet& sweep, Cell origin) const {
  // Breadth-first from `from` in a's own graph (other agents ignored), remembering each state's
  // first step; the depth at which a first step first reaches a state clear of the sweep ranks it.
  const StateGraph& g = space_.graph(a);
  auto clear = [&](StateId s) {
    const GridPose p = g.pose(s);
    return !CellSet::overlap(space_.cells(a).body(p.heading), {p.x, p.y}, sweep, origin);
  };
  // Seen states carry this search's stamp (a fresh one per search; all cleared on wrap-around).
  if (seen_.size() < static_cast<std::size_t>(g.stateIdCount())) seen_.resize(g.stateIdCount(), 0);
  if (++seen_query_ == 0) {
    std::fill(seen_.begin(), seen_.end(), 0);
    seen_query_ = 1;
  }
  auto firstSeen = [&](StateId s) {
    if (seen_[s] == seen_query_) return false;
    seen_[s] = seen_query_;
    return true;
  };
  firstSeen(from);
  StateChoices firsts;
  std::array<int, kActions> depth_of_first{};
  std::vector<EscapeItem>& queue = escape_queue_;
  queue.clear();
  g.forEachSuccessor(from, [&](Action action, StateId next) {
    if (!space_.allows(a, from, action)) return;
    depth_of_first[firsts.size()] = -1;
    queue.push_back({next, firsts.size(), 1});
    firsts.push(next);
    firstSeen(next);
  });
  int found_depth = -1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const EscapeItem item = queue[head];
    if (found_depth >= 0 && item.depth > found_depth + 1) break;
    if (depth_of_first[item.first] < 0 && clear(item.s)) {
      depth_of_first[item.first] = item.depth;
      if (found_depth < 0) found_depth = item.depth;
    }
    if (item.depth >= kEscapeDepth || queue.size() >= kEscapeStates) continue;
    g.forEachSuccessor(item.s, [&](Action action, StateId next) {
      if (!space_.allows(a, item.s, action) || !firstSeen(next)) return;
      queue.push_back({next, item.first, item.depth + 1});
    });
  }
  std::array<int, kActions> order{};
  int found = 0;
  for (int k = 0; k < firsts.size(); ++k) {
    if (depth_of_first[k] >= 0) order[found++] = k;
  }
  sortFew(order, found, [&](int x, int y) { return depth_of_first[x] < depth_of_first[y]; });
  StateChoices result;
  for (int i = 0; i < found; ++i) result.push(firsts[order[i]]);
  return result;
}

StateChoices LaPibt::cachedEscape(int a, StateId from, int pusher, StateId pusher_from, Action action) {
  // The escape depends on nothing but a's graph, the map and the pusher's sweep: the same
  // situations recur across configurations, so the answers are kept (up to a bound).
  const EscapeKey key{(static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(from),
                      (static_cast<std::uint64_t>(pusher) << 35) | (static_cast<std::uint64_t>(action) << 32) |
                          static_cast<std::uint32_t>(pusher_from)};
  const auto it = escapes_.find(key);
  if (it != escapes_.end()) return it->second;
  if (escapes_.size() >= kEscapeCache) escapes_.clear();
  const GridPose p = space_.graph(pusher).pose(pusher_from);
  const StateChoices steps = escapeSteps(a, from, space_.cells(pusher).swept(p.heading, action), {p.x, p.y});
  if (remember_escapes_) escapes_.emplace(key, steps);
  return steps;
}

bool LaPibt::assign(int a, const Config& current, Config& next, int pusher, StateId avoid) {
  assigned_[a] = true;
  chosen_[a] = Action::Wait;  // while deciding, a counts as waiting for the others
  next[a] = current[a];
  StateChoices options;
  if (pusher >= 0) {
    // Pushed: step towards the nearest state clear of the cells the pusher will sweep next
    // step. Large robots without reverse often need a turn first, so progress is enough.
    const Action action = stepAction(space_.graph(pusher), current[pusher], avoid);
    options = cachedEscape(a, current[a], pusher, current[pusher], action);
  } else {
    // Best first by distance to the target; random tie-break from the seed.
    options = candidates(a, current[a]);
    std::array<std::pair<StateId, std::uint64_t>, kActions> ranked;
    for (int i = 0; i < options.size(); ++i) ranked[i] = {options[i], rng_.next()};
    sortFew(ranked, options.size(), [&](const auto& x, const auto& y) {
      const int dx = space_.distance(a, x.first), dy = space_.distance(a, y.first);
      return dx != dy ? dx < dy : x.second < y.second;
    });
    for (int i = 0; i < options.size(); ++i) options[i] = ranked[i].first;
  }
  for (const StateId s : options) {
    if (s == current[a]) return pusher < 0;  // waiting is the best it can do
    const Action action = stepAction(space_.graph(a), current[a], s);
    std::vector<int> in_way;
    if (fits(a, current[a], action, current, &in_way)) {
      next[a] = s;
      chosen_[a] = action;
      return true;
    }
    // Blocked: if only agents still to move are in the way, ask them to clear, and wait.
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
