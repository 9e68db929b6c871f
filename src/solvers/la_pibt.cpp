#include "fleet_planner/solvers/la_pibt.h"

#include <algorithm>

#include "fleet_planner/core/collision.h"
#include "fleet_planner/solvers/space_time_astar.h"

namespace fleet_planner {

LaPibt::LaPibt(const SearchSpace& space, std::uint64_t seed)
    : space_(space), rng_(seed), chosen_(space.numAgents()), assigned_(space.numAgents()) {}

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
  for (int b = 0; b < space_.numAgents(); ++b) {
    if (b == a) continue;
    const GridPose q = space_.graph(b).pose(current[b]);
    // An agent still to move sweeps at least its current footprint, whatever it does.
    const Action other = assigned_[b] ? chosen_[b] : Action::Wait;
    if (sweepsOverlap(cells, p, action, space_.cells(b), q, other)) return false;
  }
  return true;
}

std::vector<int> LaPibt::blockers(int a, StateId from, Action action, const Config& current) const {
  std::vector<int> out;
  const GridPose p = space_.graph(a).pose(from);
  for (int b = 0; b < space_.numAgents(); ++b) {
    if (b == a || assigned_[b]) continue;
    if (sweepsOverlap(space_.cells(a), p, action, space_.cells(b), space_.graph(b).pose(current[b]), Action::Wait)) {
      out.push_back(b);
    }
  }
  return out;
}

bool LaPibt::assign(int a, const Config& current, Config& next, int pusher, StateId avoid) {
  assigned_[a] = true;
  chosen_[a] = Action::Wait;  // while deciding, a counts as waiting for the others
  next[a] = current[a];
  auto clearOfPusher = [&](StateId s) {
    if (avoid == kNoState) return true;
    const StateGraph& gp = space_.graph(pusher);
    return !footprintsOverlap(space_.cells(a), space_.graph(a).pose(s), space_.cells(pusher), gp.pose(avoid));
  };
  // Best first by distance to the target; random tie-break from the seed.
  const std::vector<StateId> options = candidates(a, current[a]);
  std::vector<std::pair<int, std::uint64_t>> ranked;
  for (std::size_t k = 0; k < options.size(); ++k) ranked.push_back({static_cast<int>(k), rng_.next()});
  std::sort(ranked.begin(), ranked.end(), [&](const auto& x, const auto& y) {
    const int dx = space_.distance(a, options[x.first]), dy = space_.distance(a, options[y.first]);
    return dx != dy ? dx < dy : x.second < y.second;
  });
  for (const auto& [k, tie] : ranked) {
    const StateId s = options[k];
    if (!clearOfPusher(s)) continue;
    const Action action = stepAction(space_.graph(a), current[a], s);
    if (fits(a, current[a], action, current)) {
      next[a] = s;
      chosen_[a] = action;
      return true;
    }
    if (s == current[a] || !clearOfPusher(current[a])) continue;
    // Blocked: if only agents still to move are in the way, ask them to clear s, and wait.
    const std::vector<int> in_way = blockers(a, current[a], action, current);
    if (in_way.empty()) continue;
    bool cleared = true;
    for (int b : in_way) {
      if (!assigned_[b]) cleared = assign(b, current, next, a, s) && cleared;
    }
    if (cleared) return true;  // a waits; the way to s opens next step
  }
  return clearOfPusher(current[a]);
}

bool LaPibt::generate(const Config& current, const std::vector<std::pair<int, StateId>>& fixed,
                      const std::vector<int>& order, Config& next) {
  const int n = space_.numAgents();
  next.assign(n, kNoState);
  std::fill(assigned_.begin(), assigned_.end(), false);
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
