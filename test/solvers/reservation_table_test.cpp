// The reservation table of moving obstacles against its definition, cell by cell and step by
// step: a robot holds the cells it sweeps during each step of its path (from step 0 on, or for
// good, for its held steps) and its last footprint from its last step on.
#include "fleet_planner/solvers/search/reservation_table.h"

#include <gtest/gtest.h>

#include <vector>

#include "fleet_planner/runtime/random.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

// Four robots of every footprint kind, one of them large.
std::vector<Robot> fleet() {
  return {dot("d", {2, 2, 0}, {2, 2, 0}), bar("b", {8, 8, 0}, {8, 8, 0}),
          triangle("p", {14, 4, 1}, {14, 4, 1}),
          makeRobot("c", Footprint::circle(1.6), {6, 15, 2}, {6, 15, 2})};
}

TEST(ReservationTable, HoldsExactlyTheCellsOfEveryStep) {
  const World w(freeMap(20, 20), fleet());
  const SearchSpace all(allRobots(w));
  const int n = all.numAgents();
  Rng rng(3);
  int taken_seen = 0, free_seen = 0;
  for (int round = 0; round < 60; ++round) {
    // Walks with pauses (runs of waits), some of their first steps held.
    std::vector<MovingObstacle> moving;
    int horizon = 0;
    for (int b = 0; b < n; ++b) {
      const StatePath walk = randomWalk(all, b, static_cast<int>(rng.uniformInt(0, 14)), rng);
      MovingObstacle m;
      m.robot = b;
      for (StateId q : walk) {
        const int repeat = rng.uniformInt(0, 3) == 0 ? static_cast<int>(rng.uniformInt(1, 5)) : 1;
        for (int k = 0; k < repeat; ++k) m.path.push_back(all.graph(b).pose(q));
      }
      if (rng.uniformInt(0, 2) == 0) {
        m.held_through = static_cast<int>(rng.uniformInt(0, static_cast<std::int64_t>(m.path.size()) - 1));
        m.held_for_good = rng.uniformInt(0, 1) == 0;
      }
      horizon = std::max(horizon, static_cast<int>(m.path.size()) + 2);
      moving.push_back(m);
    }
    const ReservationTable table(20, 20, moving, *w.graphs, all.graph(0).actionModel());
    // The definition: per cell and step (0..horizon), taken or not.
    std::vector<std::vector<char>> expected(400, std::vector<char>(horizon + 1, 0));
    auto mark = [&](const CellSet& set, const GridPose& at, int first, int last) {
      for (const Cell& c : set.cells()) {
        const int x = at.x + c.x, y = at.y + c.y;
        if (x < 0 || y < 0 || x >= 20 || y >= 20) continue;
        for (int t = first; t <= std::min(last, horizon); ++t) expected[y * 20 + x][t] = 1;
      }
    };
    for (const MovingObstacle& m : moving) {
      const FootprintCells& cells = w.graphs->cells(m.robot);
      const int end = static_cast<int>(m.path.size()) - 1;
      for (int t = 0; t < end; ++t) {
        const Action action = *actionBetween(m.path[t], m.path[t + 1], all.graph(0).actionModel());
        const bool held = t <= m.held_through;
        mark(cells.swept(m.path[t].heading, action), m.path[t], held ? 0 : t, held && m.held_for_good ? horizon : t);
      }
      mark(cells.body(m.path.back().heading), m.path.back(), end <= m.held_through ? 0 : end, horizon);
    }
    for (int cell = 0; cell < 400; ++cell) {
      for (int t = 0; t <= horizon; ++t) {
        ASSERT_EQ(table.taken(cell % 20, cell / 20, t), expected[cell][t] != 0)
            << "round " << round << ", cell (" << cell % 20 << ", " << cell / 20 << "), step " << t;
        (expected[cell][t] ? taken_seen : free_seen)++;
      }
    }
  }
  EXPECT_GT(taken_seen, 10000);
  EXPECT_GT(free_seen, 10000);
}

}  // namespace
}  // namespace fleet_planner::test
