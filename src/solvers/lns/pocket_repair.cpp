// Two agents trading places through a pocket; see pocket_repair.h.
#include "fleet_planner/solvers/lns/pocket_repair.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <queue>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "fleet_planner/model/action.h"
#include "fleet_planner/solvers/search/safe_interval_search.h"

namespace fleet_planner {

namespace {

// Breadth-first over b's graph from `from` (its start if kNoState) through states from which b
// can reach its target (and, with options.around_final_states, clear of every agent's final
// state in `table`), at most options.max_states of them: visit(s) for each in that order,
// until it returns false.
template <class Visit>
void breadthFirst(const SearchSpace& space, int b, const SoftPathTable& table, const PocketRepairOptions& options,
                  StateId from, Visit&& visit) {
  if (from == kNoState) from = space.start(b);
  const StateGraph& g = space.graph(b);
  std::vector<char> seen(static_cast<std::size_t>(g.stateIdCount()), 0);
  std::vector<StateId> queue{from};
  seen[from] = 1;
  std::vector<int> met;
  const int settled = table.lastMove() + 1;
  for (std::size_t head = 0; head < queue.size() && static_cast<long long>(head) < options.max_states; ++head) {
    const StateId s = queue[head];
    g.forEachSuccessor(s, [&](Action, StateId next) {
      if (seen[next] || space.distance(b, next) < 0) return;
      seen[next] = 1;
      if (options.around_final_states) {
        met.clear();
        table.collisionsHolding(b, next, settled, met);
        if (!met.empty()) return;
      }
      queue.push_back(next);
    });
    if (space.distance(b, s) >= 0 && !visit(s)) return;
  }
}

// Agent b standing at s for good meets no agent's final state in `table`.
bool holdable(int b, const SoftPathTable& table, StateId s) {
  std::vector<int> met;
  table.collisionsHolding(b, s, table.lastMove() + 1, met);
  return met.empty();
}

}  // namespace

std::vector<StateId> pocketsOffWay(const SearchSpace& space, int b, const SoftPathTable& table,
                                   const std::vector<char>& way, const PocketRepairOptions& options,
                                   StateId from, std::vector<StateId>* beside, std::size_t count) {
  // Pockets spread half the robot's radius apart, the footprint checks only on states far
  // enough from the pockets already found.
  const int spacing = std::max(
      1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(space.cells(b).maxNormSq())))) / 2);
  const StateGraph& g = space.graph(b);
  std::vector<StateId> pockets;
  std::vector<std::pair<int, StateId>> covering;  // (way cells covered, state), breadth-first
  if (options.max_pockets <= 0) return pockets;
  breadthFirst(space, b, table, options, from, [&](StateId s) {
    const GridPose p = g.pose(s);
    if (beside != nullptr) {  // every state's way cells counted
      int covered = 0;
      forEachMapCell(space.cells(b).body(p.heading), {p.x, p.y}, g.width(), g.height(),
                     [&](std::size_t cell) { covered += way[cell]; });
      if (covered > 0) {
        covering.emplace_back(covered, s);
        return true;
      }
    }
    const bool apart = std::all_of(pockets.begin(), pockets.end(), [&](StateId q) {
      const GridPose o = g.pose(q);
      return std::max(std::abs(o.x - p.x), std::abs(o.y - p.y)) >= spacing;
    });
    // With `beside`, the count above found no way cell.
    const bool clear = beside != nullptr || clearOfWay(space, b, s, way);
    if (apart && clear && holdable(b, table, s)) pockets.push_back(s);
    return static_cast<int>(pockets.size()) < options.max_pockets;
  });
  if (beside != nullptr && static_cast<int>(pockets.size()) < options.max_pockets) {
    std::stable_sort(covering.begin(), covering.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& [covered, s] : covering) {
      if (beside->size() >= count) break;
      if (holdable(b, table, s)) beside->push_back(s);
    }
  }
  return pockets;
}

bool passesBeside(const SearchSpace& space, int through, const StatePath& way, int b, StateId s,
                  long long max_expansions, long long& expansions) {
  const StateGraph& g = space.graph(through);
  const FootprintCells& mine = space.cells(through);
  const GridPose q = space.graph(b).pose(s);
  const CellSet& body = space.cells(b).body(q.heading);
  auto meets = [&](const GridPose& p, Action act) {
    return CellSet::overlap(mine.swept(p.heading, act), {p.x, p.y}, body, {q.x, q.y});
  };
  // The stretch of the way that meets the footprint: steps first..last (state and move on).
  int first = -1, last = -1;
  for (std::size_t t = 0; t < way.size(); ++t) {
    const GridPose p = g.pose(way[t]);
    const Action act = t + 1 < way.size()
                           ? actionBetween(p, g.pose(way[t + 1]), g.actionModel()).value_or(Action::Wait)
                           : Action::Wait;
    if (!meets(p, act)) continue;
    if (first < 0) first = static_cast<int>(t);
    last = static_cast<int>(t);
  }
  if (first < 0) return true;
  if (first == 0 || last + 1 >= static_cast<int>(way.size())) return false;
  // A* back to the way beyond the stretch (way[last + 1] or a later state) from the way's
  // states before it, each at its own step along the way: a way round may have to leave the
  // way some steps before it meets the footprint, for a turn, and join it some steps after.
  // The bound: the steps to through's target less those from way[last + 1] (the later states
  // are nearer the target). On a shortest way every state before the stretch has the same f,
  // and the latest is expanded first (deeper first among equals).
  const int beyond = space.distance(through, way[last + 1]);
  const std::unordered_set<StateId> rejoin(way.begin() + last + 1, way.end());
  auto bound = [&](StateId v) { return std::max(0, space.distance(through, v) - beyond); };
  std::unordered_map<StateId, int> cost;
  using Entry = std::tuple<int, int, StateId>;  // f, -g (deeper first), state
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  for (int t = 0; t <= first; ++t) {
    if (cost.try_emplace(way[t], t).second) open.emplace(t + bound(way[t]), -t, way[t]);
  }
  long long spent = 0;
  bool found = false;
  while (!open.empty() && spent < max_expansions) {
    const auto [f, minus_g, u] = open.top();
    open.pop();
    if (-minus_g != cost[u]) continue;
    if (rejoin.count(u) > 0) {
      found = true;
      break;
    }
    ++spent;
    const GridPose p = g.pose(u);
    g.forEachSuccessor(u, [&](Action act, StateId v) {
      if (space.distance(through, v) < 0 || !space.allows(through, u, act) || meets(p, act)) return;
      const int c = -minus_g + 1;
      const auto [it, fresh] = cost.try_emplace(v, c);
      if (!fresh && it->second <= c) return;
      it->second = c;
      open.emplace(c + bound(v), -c, v);
    });
  }
  expansions += spent;
  return found;
}

bool clearOfWay(const SearchSpace& space, int b, StateId s, const std::vector<char>& way) {
  const StateGraph& g = space.graph(b);
  const GridPose p = g.pose(s);
  return forEachMapCell(space.cells(b).body(p.heading), {p.x, p.y}, g.width(), g.height(),
                        [&](std::size_t cell) { return way[cell] == 0; });
}

void markWay(const SearchSpace& space, int a, const StatePath& path, std::vector<char>& way) {
  const StateGraph& g = space.graph(a);
  way.resize(static_cast<std::size_t>(g.width()) * g.height(), 0);
  for (std::size_t t = 0; t < path.size(); ++t) {
    const GridPose p = g.pose(path[t]);
    Action act = Action::Wait;
    if (t + 1 < path.size()) act = actionBetween(p, g.pose(path[t + 1]), g.actionModel()).value_or(Action::Wait);
    forEachMapCell(space.cells(a).swept(p.heading, act), {p.x, p.y}, g.width(), g.height(),
                   [&](std::size_t cell) { way[cell] = 1; });
  }
}

std::optional<std::vector<StatePath>> pocketRepair(const SearchSpace& space, SoftPathTable& table,
                                                   int through, const std::vector<int>& parkers,
                                                   const StatePath& through_way,
                                                   const Deadline& deadline,
                                                   const PocketRepairOptions& options,
                                                   long long& expansions) {
  if (through_way.empty() || parkers.empty()) return std::nullopt;
  std::vector<char> way;
  markWay(space, through, through_way, way);
  long long spent = 0;
  auto budget = [&] { return std::max(0LL, options.max_expansions - spent); };
  const std::size_t m = parkers.size();
  std::vector<StatePath> legs(m);  // into the pocket, at the earliest; then standing there
  // Leg 1 of parker i into one of its pockets (the first that works), parked in the table.
  auto park = [&](std::size_t i, StateId pocket) {
    SafeIntervalResult in = safeIntervalSegment(space, parkers[i], table, space.start(parkers[i]), 0, pocket,
                                                0, SoftPathTable::kNever / 2, deadline, budget());
    spent += in.expansions;
    if (in.outcome != SafeIntervalResult::Outcome::Found) return false;
    legs[i] = std::move(in.path);
    table.insert(parkers[i], legs[i]);
    return true;
  };
  auto undo = [&](std::size_t parked) {
    for (std::size_t i = 0; i < parked; ++i) table.remove(parkers[i]);
  };
  for (std::size_t i = 0; i + 1 < m; ++i) {
    bool parked = false;
    for (StateId pocket : pocketsOffWay(space, parkers[i], table, way, options)) {
      if (deadline.expired() || budget() <= 0) break;
      if ((parked = park(i, pocket))) break;
    }
    if (!parked) {
      undo(i);
      expansions += spent;
      return std::nullopt;
    }
  }
  // The last parker tries its pockets with the whole manoeuvre: the others pass, then the
  // parkers drive on, in their order, each around everything planned so far.
  // Each state beside the way costs a bounded check (outside the legs' budget: a check that
  // fails explores up to its limit); a few times as many as the pockets are looked at.
  std::vector<StateId> beside;
  std::vector<StateId> pockets =
      pocketsOffWay(space, parkers[m - 1], table, way, options, kNoState, options.beside_way ? &beside : nullptr,
                    4 * static_cast<std::size_t>(options.max_pockets));
  for (StateId s : beside) {
    if (static_cast<int>(pockets.size()) >= options.max_pockets || deadline.expired()) break;
    if (passesBeside(space, through, through_way, parkers[m - 1], s, options.beside_expansions, expansions))
      pockets.push_back(s);
  }
  for (StateId pocket : pockets) {
    if (deadline.expired() || budget() <= 0) break;
    if (!park(m - 1, pocket)) continue;
    SafeIntervalResult past = safeIntervalSearch(space, through, table, deadline, budget());
    spent += past.expansions;
    if (past.outcome != SafeIntervalResult::Outcome::Found) {
      table.remove(parkers[m - 1]);
      continue;
    }
    table.insert(through, past.path);
    std::vector<StatePath> paths{std::move(past.path)};
    for (std::size_t i = 0; i < m; ++i) {
      table.remove(parkers[i]);
      const StateId at = legs[i].back();
      const int parked_at = static_cast<int>(legs[i].size()) - 1;
      SafeIntervalResult out = safeIntervalSegment(space, parkers[i], table, at, parked_at, at,
                                                   SoftPathTable::kNever, 0, deadline, budget());
      spent += out.expansions;
      StatePath whole(legs[i].begin(), legs[i].end() - 1);
      whole.insert(whole.end(), out.path.begin(), out.path.end());
      table.insert(parkers[i], out.outcome == SafeIntervalResult::Outcome::Found ? whole : legs[i]);
      if (out.outcome != SafeIntervalResult::Outcome::Found) break;
      paths.push_back(std::move(whole));
    }
    table.remove(through);
    for (std::size_t i = 0; i < m; ++i) table.remove(parkers[i]);
    if (paths.size() == m + 1) {
      expansions += spent;
      return paths;
    }
    for (std::size_t i = 0; i + 1 < m; ++i) table.insert(parkers[i], legs[i]);
  }
  undo(m - 1);
  expansions += spent;
  return std::nullopt;
}

}  // namespace fleet_planner
