// Two agents trading places through a pocket; see pocket_repair.h.
#include "fleet_planner/solvers/lns/pocket_repair.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "fleet_planner/model/action.h"
#include "fleet_planner/solvers/search/safe_interval_search.h"

namespace fleet_planner {

// Breadth-first from `from`; the footprint checks only on states far enough from the
// pockets already found.
std::vector<StateId> pocketsOffWay(const SearchSpace& space, int b, const SoftPathTable& table,
                                   const std::vector<char>& way, const PocketRepairOptions& options,
                                   StateId from) {
  if (from == kNoState) from = space.start(b);
  const int spacing = std::max(
      1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(space.cells(b).maxNormSq())))) / 2);
  const StateGraph& g = space.graph(b);
  std::vector<char> seen(static_cast<std::size_t>(g.stateIdCount()), 0);
  std::vector<StateId> queue{from};
  seen[from] = 1;
  std::vector<StateId> pockets;
  std::vector<int> met;
  const int settled = table.lastMove() + 1;
  for (std::size_t head = 0; head < queue.size() && static_cast<int>(pockets.size()) < options.max_pockets &&
                             static_cast<long long>(head) < options.max_states;
       ++head) {
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
    const GridPose p = g.pose(s);
    const bool apart = std::all_of(pockets.begin(), pockets.end(), [&](StateId q) {
      const GridPose o = g.pose(q);
      return std::max(std::abs(o.x - p.x), std::abs(o.y - p.y)) >= spacing;
    });
    if (!apart || space.distance(b, s) < 0) continue;
    if (!clearOfWay(space, b, s, way)) continue;
    met.clear();
    table.collisionsHolding(b, s, settled, met);
    if (!met.empty()) continue;
    pockets.push_back(s);
  }
  return pockets;
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
  for (StateId pocket : pocketsOffWay(space, parkers[m - 1], table, way, options)) {
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
