// Algorithm 5's delay (delayToFit) against a brute-force reference that checks every step of a
// new path against every step of every earlier path, with no buckets, boxes or runs of waits:
// random walks with long waits (delayed starts, robots waiting for others) on a small map.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "fleet_planner/model/action.h"
#include "fleet_planner/model/collision.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/runtime/random.h"
#include "fleet_planner/layered/plan_merge.h"
#include "test_maps.h"
#include "test_robots.h"

namespace fleet_planner {
namespace {

Action actionAt(const Path& p, int t, const ActionModel& model) {
  if (t + 1 >= static_cast<int>(p.size())) return Action::Wait;
  return actionBetween(p[t], p[t + 1], model).value_or(Action::Wait);
}

// The smallest delay of `fresh` (robots' new paths) that no step of an earlier path in `merged`
// (robots marked in `done`) forbids, as plan_merge.h defines it, by checking every pair of steps.
int referenceDelay(const FleetGraphs& graphs, const std::vector<Path>& merged, const std::vector<char>& done,
                   const std::vector<int>& robots, const std::vector<Path>& fresh) {
  const ActionModel& model = graphs.graph(robots.front()).actionModel();
  std::set<int> forbidden;
  int above = -1;
  for (int r : robots) {
    if (done[r]) above = std::max(above, static_cast<int>(merged[r].size()) - 2);
  }
  for (std::size_t k = 0; k < robots.size(); ++k) {
    const Path& a = fresh[k];
    const int la = static_cast<int>(a.size()) - 1;
    for (int m = 0; m < static_cast<int>(merged.size()); ++m) {
      if (!done[m] || m == robots[k]) continue;
      const Path& b = merged[m];
      for (int tb = 0; tb + 1 < static_cast<int>(b.size()); ++tb) {
        const Action action_b = actionAt(b, tb, model);
        for (int ta = 0; ta < la && ta <= tb; ++ta) {
          if (sweepsOverlap(graphs.cells(robots[k]), a[ta], actionAt(a, ta, model), graphs.cells(m), b[tb], action_b))
            forbidden.insert(tb - ta);
        }
        if (tb - la > above && sweepsOverlap(graphs.cells(robots[k]), a[la], Action::Wait, graphs.cells(m), b[tb], action_b))
          above = tb - la;
      }
    }
  }
  int d = std::max(0, above + 1);
  while (forbidden.count(d)) ++d;
  return d;
}

// A random walk of robot r through its state graph from `from`, with waits of up to 40 steps.
Path randomWalk(const FleetGraphs& graphs, int r, const GridPose& from, int moves, Rng& rng) {
  const StateGraph& g = graphs.graph(r);
  Path p{from};
  for (int k = 0; k < moves; ++k) {
    if (rng.uniform01() < 0.2) {
      p.insert(p.end(), static_cast<std::size_t>(rng.uniformInt(1, 40)), p.back());
      continue;
    }
    std::vector<StateId> next;
    g.forEachSuccessor(g.id(p.back()), [&](Action, StateId s) { next.push_back(s); });
    if (next.empty()) break;
    p.push_back(g.pose(next[rng.uniformInt(0, static_cast<std::int64_t>(next.size()) - 1)]));
  }
  return p;
}

TEST(PlanMerge, DelayToFitEqualsTheReferenceOnRandomPathsWithLongWaits) {
  const GridMap map = test::freeMap(14, 10);
  int delayed = 0;
  for (std::uint64_t seed = 0; seed < 150; ++seed) {
    Rng rng(seed);
    Instance in;
    const int n = 3 + static_cast<int>(seed % 4);
    for (int r = 0; r < n; ++r) {
      const double radius = r % 3 == 0 ? 0.4 : r % 3 == 1 ? 0.9 : 1.4;
      const GridPose p{static_cast<int>(rng.uniformInt(2, 11)), static_cast<int>(rng.uniformInt(2, 7)), 0};
      in.robots.push_back(test::makeRobot("r" + std::to_string(r), Footprint::circle(radius), p, p));
    }
    const FleetGraphs graphs(map, test::footprintsOf(in));
    // The first n - 1 robots are merged already (with delayed starts); the last is new, and so
    // is, now and then, robot 0 again, continuing its path.
    std::vector<Path> merged(n);
    std::vector<char> done(n, 0);
    for (int r = 0; r + 1 < n; ++r) {
      merged[r] = randomWalk(graphs, r, in.robots[r].start, 12, rng);
      merged[r].insert(merged[r].begin(), static_cast<std::size_t>(rng.uniformInt(0, 60)), merged[r].front());
      done[r] = 1;
    }
    std::vector<int> robots{n - 1};
    std::vector<Path> fresh{randomWalk(graphs, n - 1, in.robots[n - 1].start, 12, rng)};
    if (seed % 3 == 0) {
      robots.push_back(0);
      fresh.push_back(randomWalk(graphs, 0, merged[0].back(), 8, rng));
    }
    const int expected = referenceDelay(graphs, merged, done, robots, fresh);
    std::vector<Path> shifted = fresh;
    const int d = delayToFit(graphs, merged, done, robots, shifted);
    ASSERT_EQ(d, expected) << "seed " << seed;
    for (std::size_t k = 0; k < fresh.size(); ++k) EXPECT_EQ(shifted[k].size(), fresh[k].size() + d);
    delayed += d > 0;
  }
  EXPECT_GT(delayed, 100) << "too few instances where the delay matters";
}

}  // namespace
}  // namespace fleet_planner
