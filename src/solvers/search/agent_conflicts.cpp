#include "fleet_planner/solvers/search/agent_conflicts.h"

#include <algorithm>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/solvers/search/space_time_astar.h"

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

// A box of map cells, inclusive.
struct Box {
  int x0, y0, x1, y1;
};

// The pairs (i < j), sorted, whose boxes overlap, found by sorting on the boxes' left edges and
// sweeping: two footprints whose boxes do not overlap share no cell, so checking these pairs
// only finds every conflict of the step, in the same order as checking every pair.
void overlappingPairs(const std::vector<Box>& boxes, const std::vector<int>& agents,
                      std::vector<int>& by_x, std::vector<std::pair<int, int>>& pairs) {
  by_x = agents;
  std::sort(by_x.begin(), by_x.end(), [&](int a, int b) {
    return boxes[a].x0 != boxes[b].x0 ? boxes[a].x0 < boxes[b].x0 : a < b;
  });
  pairs.clear();
  for (std::size_t k = 0; k < by_x.size(); ++k) {
    const Box& a = boxes[by_x[k]];
    for (std::size_t l = k + 1; l < by_x.size() && boxes[by_x[l]].x0 <= a.x1; ++l) {
      const Box& b = boxes[by_x[l]];
      if (b.y0 <= a.y1 && a.y0 <= b.y1)
        pairs.emplace_back(std::min(by_x[k], by_x[l]), std::max(by_x[k], by_x[l]));
    }
  }
  std::sort(pairs.begin(), pairs.end());
}

// Calls f(conflict) for conflicts in step order (at one step by agent pair, a pair's vertex
// conflict at t + 1 before its transfer of t); stops when f returns true. Each step checks only
// the pairs whose sweeps' boxes overlap: a sweep holds the bodies before and after its action
// (footprint_cells.h), so it bounds every cell of the three checks, and a fleet of hundreds has
// few such pairs among its n^2 / 2.
template <class F>
void forEachConflict(const SearchSpace& space, const std::vector<StatePath>& paths, F&& f) {
  const int n = static_cast<int>(paths.size());
  const int T = horizon(paths);
  std::vector<Motion> m(n);
  std::vector<Box> boxes(n);
  std::vector<int> agents, by_x;
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < n; ++i) {
    if (!paths[i].empty()) agents.push_back(i);
  }
  for (int t = 0; t < std::max(T, 1); ++t) {
    for (int i : agents) {
      m[i] = motionAt(space, paths, i, t);
      const CellSet& sweep = space.cells(i).swept(m[i].from.heading, m[i].action);
      const GridPose& p = m[i].from;
      boxes[i] = {p.x + sweep.minX(), p.y + sweep.minY(), p.x + sweep.maxX(), p.y + sweep.maxY()};
    }
    overlappingPairs(boxes, agents, by_x, pairs);
    for (const auto& [i, j] : pairs) {
      const FootprintCells &ci = space.cells(i), &cj = space.cells(j);
      Cell c;
      if (t == 0 &&
          CellSet::commonCell(ci.body(m[i].from.heading), {m[i].from.x, m[i].from.y},
                              cj.body(m[j].from.heading), {m[j].from.x, m[j].from.y}, c)) {
        if (f(AgentConflict{AgentConflict::Kind::Vertex, i, j, 0, c})) return;
        continue;
      }
      if (T == 0) continue;
      if (CellSet::commonCell(ci.body(m[i].to.heading), {m[i].to.x, m[i].to.y},
                              cj.body(m[j].to.heading), {m[j].to.x, m[j].to.y}, c)) {
        if (f(AgentConflict{AgentConflict::Kind::Vertex, i, j, t + 1, c})) return;
      } else if (CellSet::commonCell(
                     ci.swept(m[i].from.heading, m[i].action), {m[i].from.x, m[i].from.y},
                     cj.swept(m[j].from.heading, m[j].action), {m[j].from.x, m[j].from.y}, c)) {
        if (f(AgentConflict{AgentConflict::Kind::Transfer, i, j, t, c})) return;
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

std::vector<AgentConflict> earliestConflictPerPair(const SearchSpace& space, const std::vector<StatePath>& paths,
                                                   int max_count) {
  return earliestConflictPerPair(space, paths, max_count, [](const AgentConflict&) { return true; });
}

std::vector<AgentConflict> earliestConflictPerPair(const SearchSpace& space, const std::vector<StatePath>& paths,
                                                   int max_count,
                                                   const std::function<bool(const AgentConflict&)>& accept) {
  std::vector<AgentConflict> found;
  if (max_count <= 0) return found;
  const std::size_t n = paths.size();
  std::vector<bool> seen(n * n, false);
  forEachConflict(space, paths, [&](const AgentConflict& c) {
    const std::size_t pair = static_cast<std::size_t>(c.a) * n + static_cast<std::size_t>(c.b);
    if (seen[pair] || !accept(c)) return false;
    seen[pair] = true;
    found.push_back(c);
    return static_cast<int>(found.size()) >= max_count;
  });
  return found;
}

std::vector<std::pair<int, int>> conflictingPairs(const SearchSpace& space, const std::vector<StatePath>& paths) {
  return tallyConflicts(space, paths).pairs;
}

ConflictTally tallyConflicts(const SearchSpace& space, const std::vector<StatePath>& paths) {
  const std::size_t n = paths.size();
  std::vector<bool> seen(n * n, false);
  ConflictTally tally;
  forEachConflict(space, paths, [&](const AgentConflict& c) {
    ++tally.conflicts;
    const std::size_t pair = static_cast<std::size_t>(c.a) * n + static_cast<std::size_t>(c.b);
    if (!seen[pair]) tally.pairs.emplace_back(c.a, c.b);
    seen[pair] = true;
    return false;
  });
  std::sort(tally.pairs.begin(), tally.pairs.end());
  return tally;
}

int countConflicts(const SearchSpace& space, const std::vector<StatePath>& paths) {
  int count = 0;
  forEachConflict(space, paths, [&](const AgentConflict&) {
    ++count;
    return false;
  });
  return count;
}

ConflictAvoidanceTable::ConflictAvoidanceTable(const SearchSpace& space, const std::vector<StatePath>& paths,
                                               int agent)
    : space_(space), agent_(agent) {
  const int T = horizon(paths);
  steps_.resize(T + 1);
  for (int t = 0; t <= T; ++t) {
    for (int j = 0; j < static_cast<int>(paths.size()); ++j) {
      if (j == agent || paths[j].empty()) continue;
      const auto mj = motionAt(space, paths, j, t);
      steps_[t].push_back({&space.cells(j).swept(mj.from.heading, mj.action), {mj.from.x, mj.from.y}});
    }
  }
}

int ConflictAvoidanceTable::conflicts(StateId s, Action action, int t) const {
  if (steps_.empty()) return 0;
  const GridPose p = space_.graph(agent_).pose(s);
  const CellSet& mine = space_.cells(agent_).swept(p.heading, action);
  int count = 0;
  for (const Motion& m : steps_[std::min<std::size_t>(t, steps_.size() - 1)]) {
    if (CellSet::overlap(mine, {p.x, p.y}, *m.cells, m.origin)) ++count;
  }
  return count;
}

}  // namespace fleet_planner
