// The conflicts between paths (agent_conflicts.h) that the backends and the plans' checks use:
// found by checking only the pairs of robots near each other, they are every conflict that
// checking every pair at every step finds, in the same order.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "fleet_planner/solvers/search/agent_conflicts.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "large_robot_walks.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

// Agent a's motion during step t of its path.
struct GraphAt {
  GraphAt(const SearchSpace& space, const std::vector<StatePath>& paths, int a, int t)
      : cells(space.cells(a)) {
    const StateGraph& g = space.graph(a);
    const StateId s = stateAt(paths[a], t), n = stateAt(paths[a], t + 1);
    from = g.pose(s);
    to = g.pose(n);
    action = stepAction(g, s, n);
  }
  const FootprintCells& cells;
  GridPose from, to;
  Action action;
};

// Every conflict, by checking every pair of agents at every step: at step 0 a pair's bodies
// before it (a conflict there is the pair's only one of the step), then each pair's bodies
// after the step, else its sweeps during the step; steps in order, pairs in order.
std::vector<AgentConflict> everyConflict(const SearchSpace& space,
                                         const std::vector<StatePath>& paths) {
  std::vector<AgentConflict> found;
  const int n = static_cast<int>(paths.size());
  int T = 0;
  for (const StatePath& p : paths) T = std::max(T, static_cast<int>(p.size()) - 1);
  for (int t = 0; t < std::max(T, 1); ++t) {
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        if (paths[i].empty() || paths[j].empty()) continue;
        const GraphAt gi(space, paths, i, t), gj(space, paths, j, t);
        Cell c;
        if (t == 0 &&
            CellSet::commonCell(gi.cells.body(gi.from.heading), {gi.from.x, gi.from.y},
                                gj.cells.body(gj.from.heading), {gj.from.x, gj.from.y}, c)) {
          found.push_back({AgentConflict::Kind::Vertex, i, j, 0, c});
          continue;
        }
        if (T == 0) continue;
        if (CellSet::commonCell(gi.cells.body(gi.to.heading), {gi.to.x, gi.to.y},
                                gj.cells.body(gj.to.heading), {gj.to.x, gj.to.y}, c)) {
          found.push_back({AgentConflict::Kind::Vertex, i, j, t + 1, c});
        } else if (CellSet::commonCell(
                       gi.cells.swept(gi.from.heading, gi.action), {gi.from.x, gi.from.y},
                       gj.cells.swept(gj.from.heading, gj.action), {gj.from.x, gj.from.y}, c)) {
          found.push_back({AgentConflict::Kind::Transfer, i, j, t, c});
        }
      }
    }
  }
  return found;
}

bool same(const AgentConflict& x, const AgentConflict& y) {
  return x.kind == y.kind && x.a == y.a && x.b == y.b && x.t == y.t && x.cell.x == y.cell.x &&
         x.cell.y == y.cell.y;
}

// The five queries of agent_conflicts.h against everyConflict() on `paths`; the number of
// conflicts found.
int checkQueries(const SearchSpace& space, const std::vector<StatePath>& paths,
                 const std::string& where) {
  const std::vector<AgentConflict> all = everyConflict(space, paths);
  EXPECT_EQ(countConflicts(space, paths), static_cast<int>(all.size())) << where;
  const std::optional<AgentConflict> first = firstConflict(space, paths);
  EXPECT_EQ(first.has_value(), !all.empty()) << where;
  if (first && !all.empty()) EXPECT_TRUE(same(*first, all.front())) << where;
  std::vector<AgentConflict> earliest;
  std::vector<std::pair<int, int>> pairs;
  for (const AgentConflict& c : all) {
    if (std::find(pairs.begin(), pairs.end(), std::make_pair(c.a, c.b)) != pairs.end()) continue;
    pairs.emplace_back(c.a, c.b);
    earliest.push_back(c);
  }
  const std::vector<AgentConflict> got = earliestConflictPerPair(space, paths, 1 << 20);
  EXPECT_EQ(got.size(), earliest.size()) << where;
  for (std::size_t k = 0; k < std::min(got.size(), earliest.size()); ++k)
    EXPECT_TRUE(same(got[k], earliest[k])) << where << ", pair " << k;
  std::sort(pairs.begin(), pairs.end());
  EXPECT_EQ(conflictingPairs(space, paths), pairs) << where;
  const ConflictTally tally = tallyConflicts(space, paths);
  EXPECT_EQ(tally.conflicts, static_cast<int>(all.size())) << where;
  EXPECT_EQ(tally.pairs, pairs) << where;
  return static_cast<int>(all.size());
}

// Large robots of 4-11 cells close together, random walks: the sweeps and bodies of robots
// whose boxes barely touch.
TEST(AgentConflicts, LargeRobotsCloseTogetherAsEveryPairChecked) {
  const World w(freeMap(40, 40), largeRobots());
  const SearchSpace space(allRobots(w));
  Rng rng(11);
  int conflicts = 0;
  for (int round = 0; round < 200; ++round) {
    std::vector<StatePath> walks;
    for (int a = 0; a < space.numAgents(); ++a)
      walks.push_back(randomWalk(space, a, static_cast<int>(rng.uniformInt(0, 12)), rng));
    conflicts += checkQueries(space, walks, "round " + std::to_string(round));
  }
  EXPECT_GT(conflicts, 200);
}

// A generated fleet of 60 robots on a small map (circles, blocks, polygons; some empty paths):
// many pairs, few of them near each other at a step.
TEST(AgentConflicts, AGeneratedFleetAsEveryPairChecked) {
  const GridMap map = freeMap(48, 48);
  const World w(map, generatedRobots(map, 60, 5));
  const SearchSpace space(allRobots(w));
  Rng rng(3);
  int conflicts = 0;
  for (int round = 0; round < 20; ++round) {
    std::vector<StatePath> walks;
    for (int a = 0; a < space.numAgents(); ++a) {
      walks.push_back(randomWalk(space, a, static_cast<int>(rng.uniformInt(0, 30)), rng));
      if (rng.uniformInt(0, 19) == 0) walks.back().clear();
    }
    conflicts += checkQueries(space, walks, "round " + std::to_string(round));
  }
  EXPECT_GT(conflicts, 100);
}

}  // namespace
}  // namespace fleet_planner::test
