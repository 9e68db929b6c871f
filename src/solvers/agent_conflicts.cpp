#include "fleet_planner/solvers/agent_conflicts.h"

#include <algorithm>

#include "fleet_planner/core/collision.h"
#include "fleet_planner/solvers/space_time_astar.h"

namespace fleet_planner {

namespace {

int horizon(const std::vector<StatePath>& paths) {
  int h = 0;
  for (const auto& p : paths) h = std::max(h, static_cast<int>(p.size()) - 1);
  return h;
}

struct Motion {
  GridPose from, to;
  Action action;
};

Motion motionAt(const SearchSpace& space, const std::vector<StatePath>& paths, int a, int t) {
  const StateGraph& g = space.graph(a);
  const StateId s = stateAt(paths[a], t), n = stateAt(paths[a], t + 1);
  return {g.pose(s), g.pose(n), stepAction(g, s, n)};
}

// Calls f(conflict) for conflicts in step order; stops when f returns true.
template <class F>
void forEachConflict(const SearchSpace& space, const std::vector<StatePath>& paths, F&& f) {
  const int n = static_cast<int>(paths.size());
  const int T = horizon(paths);
  std::vector<Motion> m(n);
  for (int t = 0; t < std::max(T, 1); ++t) {
    for (int i = 0; i < n; ++i) m[i] = motionAt(space, paths, i, t);
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        if (t == 0 && footprintsOverlap(space.cells(i), m[i].from, space.cells(j), m[j].from)) {
          if (f(AgentConflict{AgentConflict::Kind::Vertex, i, j, 0})) return;
          continue;
        }
        if (T == 0) continue;
        if (footprintsOverlap(space.cells(i), m[i].to, space.cells(j), m[j].to)) {
          if (f(AgentConflict{AgentConflict::Kind::Vertex, i, j, t + 1})) return;
        } else if (sweepsOverlap(space.cells(i), m[i].from, m[i].action, space.cells(j), m[j].from, m[j].action)) {
          if (f(AgentConflict{AgentConflict::Kind::Transfer, i, j, t})) return;
        }
      }
    }
  }
}

}  // namespace

std::optional<AgentConflict> firstConflict(const SearchSpace& space, const std::vector<StatePath>& paths) {
  std::optional<AgentConflict> first;
  forEachConflict(space, paths, [&](const AgentConflict& c) {
    first = c;
    return true;
  });
  return first;
}

int countConflicts(const SearchSpace& space, const std::vector<StatePath>& paths) {
  int count = 0;
  forEachConflict(space, paths, [&](const AgentConflict&) {
    ++count;
    return false;
  });
  return count;
}

int conflictsWith(const SearchSpace& space, const std::vector<StatePath>& paths, int a, StateId s, Action action,
                  int t) {
  const StateGraph& ga = space.graph(a);
  const GridPose from = ga.pose(s);
  int count = 0;
  for (int j = 0; j < static_cast<int>(paths.size()); ++j) {
    if (j == a || paths[j].empty()) continue;
    const Motion mj = motionAt(space, paths, j, t);
    if (sweepsOverlap(space.cells(a), from, action, space.cells(j), mj.from, mj.action)) ++count;
  }
  return count;
}

}  // namespace fleet_planner
