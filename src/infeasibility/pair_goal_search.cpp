// The backward search of a pair's goal; see pair_goal_search.h.
#include "fleet_planner/infeasibility/pair_goal_search.h"

#include <cstdint>
#include <deque>
#include <unordered_set>
#include <utility>
#include <vector>

#include "fleet_planner/model/collision.h"

namespace fleet_planner {

namespace {

struct Step {
  Action action;
  StateId from;
};

// The ways into state s in one step: a wait, or an edge from a predecessor.
std::vector<Step> waysInto(const StateGraph& g, StateId s) {
  std::vector<Step> out{{Action::Wait, s}};
  g.forEachPredecessor(s, [&](Action a, StateId p) { out.push_back({a, p}); });
  return out;
}

}  // namespace

PairSearch searchPairBackwards(const FleetGraphs& graphs, const PairEnds& a, const PairEnds& b,
                               long long max_configurations, const Deadline& deadline) {
  const StateGraph &A = graphs.graph(a.robot), &B = graphs.graph(b.robot);
  const FootprintCells &cells_a = A.cells(), &cells_b = B.cells();
  const StateId start_a = A.id(a.start), start_b = B.id(b.start);
  const StateId goal_a = A.id(a.target), goal_b = B.id(b.target);
  if (!A.valid(start_a) || !A.valid(goal_a) || !B.valid(start_b) || !B.valid(goal_b))
    return {PairReach::Unreachable, 0};
  if (footprintsOverlap(cells_a, a.target, cells_b, b.target)) return {PairReach::Unreachable, 0};
  if (start_a == goal_a && start_b == goal_b) return {PairReach::Reachable, 1};
  const auto key = [&](StateId x, StateId y) {
    return static_cast<std::uint64_t>(x) * static_cast<std::uint64_t>(B.stateIdCount()) +
           static_cast<std::uint64_t>(y);
  };
  std::unordered_set<std::uint64_t> seen{key(goal_a, goal_b)};
  std::deque<std::pair<StateId, StateId>> queue{{goal_a, goal_b}};
  const auto found = [&] { return static_cast<long long>(seen.size()); };
  while (!queue.empty()) {
    if (found() > max_configurations || deadline.expired()) return {PairReach::Unknown, found()};
    const auto [sa, sb] = queue.front();
    queue.pop_front();
    const std::vector<Step> into_a = waysInto(A, sa), into_b = waysInto(B, sb);
    for (const Step& x : into_a) {
      const GridPose pa = A.pose(x.from);
      for (const Step& y : into_b) {
        if (x.action == Action::Wait && y.action == Action::Wait) continue;
        const std::uint64_t k = key(x.from, y.from);
        const GridPose pb = B.pose(y.from);
        // The plan validator's checks of a step: the footprints before it, and the sweeps.
        if (seen.count(k) || footprintsOverlap(cells_a, pa, cells_b, pb) ||
            sweepsOverlap(cells_a, pa, x.action, cells_b, pb, y.action)) {
          continue;
        }
        seen.insert(k);
        if (x.from == start_a && y.from == start_b) return {PairReach::Reachable, found()};
        queue.push_back({x.from, y.from});
      }
    }
  }
  return {PairReach::Unreachable, found()};
}

}  // namespace fleet_planner
