// Returning robots clear the stage for a plan made without them; see stage_clearing.h.
#include "fleet_planner/solvers/lns/stage_clearing.h"

#include <algorithm>

#include "fleet_planner/model/action.h"
#include "fleet_planner/solvers/lns/pocket_repair.h"
#include "fleet_planner/solvers/search/safe_interval_search.h"
#include "fleet_planner/solvers/search/soft_path_table.h"

namespace fleet_planner {

namespace {

// Agent a's path drives only where the search space lets it (static footprints, standing
// robots) and meets no reserved cells of other subproblems' timed paths.
bool drivable(const SearchSpace& space, int a, const StatePath& path) {
  const StateGraph& g = space.graph(a);
  const ReservationTable& reservations = space.reservations();
  for (std::size_t t = 0; t < path.size(); ++t) {
    const GridPose p = g.pose(path[t]);
    Action act = Action::Wait;
    if (t + 1 < path.size()) {
      const std::optional<Action> next = actionBetween(p, g.pose(path[t + 1]), g.actionModel());
      if (!next) return false;
      act = *next;
    }
    if (!space.allows(a, path[t], act)) return false;
    if (!reservations.empty() &&
        reservations.taken(space.probe(a, p.heading, act), {p.x, p.y}, static_cast<int>(t)))
      return false;
  }
  return true;
}

}  // namespace

std::optional<std::vector<StatePath>> clearTheStage(const SearchSpace& space, const std::vector<bool>& returning,
                                                    const std::vector<StatePath>& alone, const Deadline& deadline,
                                                    int max_pockets, long long max_expansions,
                                                    long long& expansions) {
  const int n = space.numAgents();
  std::vector<char> stage;
  std::vector<int> movers, in_way;
  for (int a = 0; a < n; ++a) {
    if (returning[a]) continue;
    if (alone[a].empty() || alone[a].front() != space.start(a) || alone[a].back() != space.target(a) ||
        !drivable(space, a, alone[a]))
      return std::nullopt;
    movers.push_back(a);
    markWay(space, a, alone[a], stage);
  }
  if (movers.empty()) return std::nullopt;
  for (int a = 0; a < n; ++a) {
    if (!returning[a]) continue;
    const StateGraph& g = space.graph(a);
    const GridPose p = g.pose(space.start(a));
    const bool clear = forEachMapCell(space.cells(a).body(p.heading), {p.x, p.y}, g.width(), g.height(),
                                      [&](std::size_t cell) { return stage[cell] == 0; });
    if (!clear) in_way.push_back(a);
  }
  if (in_way.empty()) return std::nullopt;

  // Everybody stands where it starts; the robots in the way leave one after the other.
  SoftPathTable table(space);
  for (int a = 0; a < n; ++a) table.insert(a, StatePath{space.start(a)});
  long long spent = 0;
  PocketRepairOptions pocket_options;
  pocket_options.max_pockets = max_pockets;
  std::vector<StatePath> paths(n);
  std::vector<int> parked_at(n, 0);
  int delay = 0;
  for (int s : in_way) {
    table.remove(s);
    bool parked = false;
    for (StateId pocket : pocketsOffWay(space, s, table, stage, pocket_options)) {
      if (deadline.expired() || spent >= max_expansions) break;
      SafeIntervalResult leg = safeIntervalSegment(space, s, table, space.start(s), 0, pocket, 0,
                                                   SoftPathTable::kNever / 2, deadline, max_expansions - spent);
      spent += leg.expansions;
      if (leg.outcome != SafeIntervalResult::Outcome::Found) continue;
      parked_at[s] = static_cast<int>(leg.path.size()) - 1;
      delay = std::max(delay, parked_at[s]);
      paths[s] = std::move(leg.path);
      parked = true;
      break;
    }
    table.insert(s, parked ? paths[s] : StatePath{space.start(s)});
    if (!parked) {
      expansions += spent;
      return std::nullopt;
    }
  }
  // The plan made without them, delayed until every robot in the way has parked (conflict-free
  // among themselves, so each is checked against the others' paths only).
  for (int a : movers) table.remove(a);
  for (int a : movers) {
    StatePath p(static_cast<std::size_t>(delay), space.start(a));
    p.insert(p.end(), alone[a].begin(), alone[a].end());
    // Delayed, it meets other subproblems' timed paths at other steps than the plan did.
    if (!drivable(space, a, p) || !table.partners(a, p).empty()) {
      expansions += spent;
      return std::nullopt;
    }
    table.insert(a, p);
    paths[a] = std::move(p);
  }
  // Back where they stood, the last to leave first.
  for (auto it = in_way.rbegin(); it != in_way.rend(); ++it) {
    const int s = *it;
    table.remove(s);
    const StateId pocket = paths[s].back();
    SafeIntervalResult back = safeIntervalSegment(space, s, table, pocket, parked_at[s], pocket,
                                                  SoftPathTable::kNever, 0, deadline,
                                                  std::max(0LL, max_expansions - spent));
    spent += back.expansions;
    if (back.outcome != SafeIntervalResult::Outcome::Found) {
      expansions += spent;
      return std::nullopt;
    }
    paths[s].pop_back();
    paths[s].insert(paths[s].end(), back.path.begin(), back.path.end());
    table.insert(s, paths[s]);
  }
  expansions += spent;
  for (int a = 0; a < n; ++a) {
    if (paths[a].empty()) paths[a] = StatePath{space.start(a)};
  }
  if (firstConflict(space, paths)) return std::nullopt;
  return paths;
}

}  // namespace fleet_planner
