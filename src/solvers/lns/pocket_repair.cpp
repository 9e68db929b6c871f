// Two agents trading places through a pocket; see pocket_repair.h.
#include "fleet_planner/solvers/lns/pocket_repair.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "fleet_planner/solvers/search/safe_interval_search.h"

namespace fleet_planner {

namespace {

// Pockets for agent b: states reachable from its start (breadth-first over its graph's edges)
// from which it can reach its target, where b's footprint covers no cell of `way` (true: a cell
// that agent a's footprint covers on its way) and meets no agent's final state in `table`,
// spread `spacing` cells apart (Chebyshev), the nearest first. A filter only: the legs' searches
// decide, so the way's rotation sweeps and the static sweeps of b's edges are left out.
std::vector<StateId> pocketsFor(const SearchSpace& space, int b, const SoftPathTable& table,
                                const std::vector<char>& way, int spacing,
                                const PocketRepairOptions& options) {
  const StateGraph& g = space.graph(b);
  std::vector<char> seen(static_cast<std::size_t>(g.stateIdCount()), 0);
  std::vector<StateId> queue{space.start(b)};
  seen[space.start(b)] = 1;
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
      queue.push_back(next);
    });
    const GridPose p = g.pose(s);
    const bool apart = std::all_of(pockets.begin(), pockets.end(), [&](StateId q) {
      const GridPose o = g.pose(q);
      return std::max(std::abs(o.x - p.x), std::abs(o.y - p.y)) >= spacing;
    });
    if (!apart || space.distance(b, s) < 0) continue;
    const bool clear = forEachMapCell(space.cells(b).body(p.heading), {p.x, p.y}, g.width(), g.height(),
                                      [&](std::size_t cell) { return way[cell] == 0; });
    if (!clear) continue;
    met.clear();
    table.collisionsHolding(b, s, settled, met);
    if (!met.empty()) continue;
    pockets.push_back(s);
  }
  return pockets;
}

// The cells agent a's footprint covers at the states of `path`.
std::vector<char> cellsOfWay(const SearchSpace& space, int a, const StatePath& path) {
  const StateGraph& g = space.graph(a);
  std::vector<char> way(static_cast<std::size_t>(g.width()) * g.height(), 0);
  StateId last = kNoState;
  for (StateId s : path) {
    if (s == last) continue;
    last = s;
    const GridPose p = g.pose(s);
    forEachMapCell(space.cells(a).body(p.heading), {p.x, p.y}, g.width(), g.height(),
                   [&](std::size_t cell) { way[cell] = 1; });
  }
  return way;
}

}  // namespace

std::optional<std::vector<StatePath>> pocketRepair(const SearchSpace& space, SoftPathTable& table,
                                                   int through, int parks,
                                                   const StatePath& through_way,
                                                   const Deadline& deadline,
                                                   const PocketRepairOptions& options,
                                                   long long& expansions) {
  if (through_way.empty()) return std::nullopt;
  const int radius =
      static_cast<int>(std::ceil(std::sqrt(static_cast<double>(space.cells(parks).maxNormSq()))));
  const std::vector<StateId> pockets =
      pocketsFor(space, parks, table, cellsOfWay(space, through, through_way), std::max(1, radius / 2), options);
  long long spent = 0;
  auto budget = [&] { return options.max_expansions - spent; };
  for (StateId pocket : pockets) {
    if (deadline.expired() || budget() <= 0) break;
    // Leg 1: into the pocket, at the earliest; the path then stands there for good.
    SafeIntervalResult in = safeIntervalSegment(space, parks, table, space.start(parks), 0, pocket, 0,
                                                SoftPathTable::kNever / 2, deadline, budget());
    spent += in.expansions;
    if (in.outcome != SafeIntervalResult::Outcome::Found) continue;
    table.insert(parks, in.path);
    SafeIntervalResult past = safeIntervalSearch(space, through, table, deadline, budget());
    spent += past.expansions;
    table.remove(parks);
    if (past.outcome != SafeIntervalResult::Outcome::Found) continue;
    // Leg 3: out of the pocket once parked, around the other's path.
    table.insert(through, past.path);
    const int parked_at = static_cast<int>(in.path.size()) - 1;
    SafeIntervalResult out = safeIntervalSegment(space, parks, table, pocket, parked_at, pocket,
                                                 SoftPathTable::kNever, 0, deadline, budget());
    spent += out.expansions;
    table.remove(through);
    if (out.outcome != SafeIntervalResult::Outcome::Found) continue;
    expansions += spent;
    StatePath parked(in.path.begin(), in.path.end() - 1);
    parked.insert(parked.end(), out.path.begin(), out.path.end());
    return std::vector<StatePath>{std::move(past.path), std::move(parked)};
  }
  expansions += spent;
  return std::nullopt;
}

}  // namespace fleet_planner
