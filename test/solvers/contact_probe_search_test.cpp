// Contact probes in the searches (SearchSpace::probe, contact_probe.h): with robots large enough
// that a probe is a fraction of its sweep, the soft path table and the reservation table answer
// exactly as the whole sweeps do.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/solvers/search/soft_path_table.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "large_robot_walks.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

TEST(ContactProbeSearch, ProbesAreSmallerThanTheSweeps) {
  const World w(freeMap(40, 40), largeRobots());
  const SearchSpace space(allRobots(w));
  for (int a = 0; a < 4; ++a) {  // not the small disc
    for (int h = 0; h < kHeadings; ++h) {
      const CellSet& sweep = space.cells(a).swept(h, Action::RotateCcw);
      EXPECT_LT(space.probe(a, h, Action::RotateCcw).size() * 2, sweep.size()) << space.label(a);
    }
  }
}

// The small disc standing inside the wide block's footprint, off its centre, where only the
// probe's inner grid can find it: in the soft path table and as a moving obstacle.
TEST(ContactProbeSearch, ARobotInsideAnotherIsFound) {
  std::vector<Robot> robots = largeRobots();
  const World w(freeMap(40, 40), {robots[3], robots[4]});
  const GridPose wide{20, 30, 0}, inside{22, 30, 0};  // two cells off the centre, along its length
  const int wide_cells = static_cast<int>(w.graphs->cells(0).body(0).size());
  ASSERT_TRUE(w.graphs->cells(0).body(0).contains(3, 1) && w.graphs->cells(0).body(0).contains(4, 2)) << wide_cells;

  const SearchSpace space(allRobots(w));
  const StateId s = space.graph(0).id(wide);
  ASSERT_NE(s, kNoState);
  SoftPathTable table(space);
  table.insert(1, {space.graph(1).id(inside)});
  std::vector<std::pair<int, int>> runs;
  int forever = SoftPathTable::kNever;
  table.unsafeRuns(0, s, Action::Wait, runs, forever);
  EXPECT_EQ(forever, 0);
  std::vector<int> met;
  table.collisions(0, s, Action::Wait, 5, met);
  EXPECT_EQ(met, std::vector<int>{1});

  Subproblem sub = allRobots(w);
  sub.robots = {0};
  MovingObstacle m;
  m.robot = 1;
  m.path = {inside};
  sub.moving.push_back(m);
  const SearchSpace planned(sub);
  const CellSet& probe = planned.probe(0, 0, Action::Wait);
  EXPECT_LT(probe.size(), static_cast<std::size_t>(wide_cells));
  EXPECT_TRUE(planned.reservations().taken(probe, {wide.x, wide.y}, 3));
  EXPECT_EQ(planned.reservations().lastTaken(probe, {wide.x, wide.y}), ReservationTable::kForever);
}

// The soft path table's collisions (through partners) and unsafe steps against every pair of
// sweeps, step by step, on random walks.
TEST(ContactProbeSearch, SoftPathTableFindsEveryContact) {
  const World w(freeMap(40, 40), largeRobots());
  const SearchSpace space(allRobots(w));
  Rng rng(3);
  int pairs_seen = 0, unsafe_seen = 0;
  for (int round = 0; round < 150; ++round) {
    SoftPathTable table(space);
    std::vector<StatePath> walks = walksInto(table, space, rng);
    const std::vector<std::pair<int, int>> from_table = partnerPairs(table, space.numAgents());
    ASSERT_EQ(from_table, conflictingPairs(space, walks)) << "round " << round;
    pairs_seen += static_cast<int>(from_table.size());

    const int a = static_cast<int>(rng.uniformInt(0, space.numAgents() - 1));
    const StateId s = somewhere(space, a, walks, rng);
    const GridPose p = space.graph(a).pose(s);
    for (int act = 0; act < kActions; ++act) {
      const Action action = static_cast<Action>(act);
      if (!space.allows(a, s, action)) continue;
      std::vector<std::pair<int, int>> runs;
      int forever = SoftPathTable::kNever;
      table.unsafeRuns(a, s, action, runs, forever);
      for (int t = 0; t <= table.lastMove() + 2; ++t) {
        bool expected = false;
        for (int b = 0; b < space.numAgents(); ++b) {
          if (b == a) continue;
          const StateId q = stateAt(walks[b], t), n = stateAt(walks[b], t + 1);
          expected = expected || sweepsOverlap(space.cells(a), p, action, space.cells(b), space.graph(b).pose(q),
                                               stepAction(space.graph(b), q, n));
        }
        const bool found = t >= forever || std::any_of(runs.begin(), runs.end(), [t](const auto& r) {
                             return r.first <= t && t <= r.second;
                           });
        ASSERT_EQ(found, expected) << "round " << round << ", " << space.label(a) << ", step " << t;
        unsafe_seen += expected ? 1 : 0;
      }
    }
  }
  EXPECT_GT(pairs_seen, 30);
  EXPECT_GT(unsafe_seen, 30);
}

// A move's sweep is its body before, its body after and the extra cells (SearchSpace::moveExtra),
// for every robot shape, heading and move that has them, at lattice steps 1 to 3: every straight
// move and a disc's turns; a block's straight moves have no extra cells.
TEST(ContactProbeSearch, AMoveIsItsTwoBodiesAndItsExtraCells) {
  for (int step = 1; step <= 3; ++step) {
    ActionModel model;
    model.step = step;
    model.allow_backward = true;
    const LargeRobotsOn scene(model);
    const SearchSpace& space = scene.space;
    for (int a = 0; a < space.numAgents(); ++a) {
      for (int h = 0; h < kHeadings; ++h) {
        const StateId s = space.graph(a).id({20, 20, h});
        for (Action action : {Action::Forward, Action::Backward, Action::RotateCcw, Action::RotateCw}) {
          const CellSet* extra = space.moveExtra(a, h, action);
          const bool straight = action == Action::Forward || action == Action::Backward;
          if (straight || a == 0) ASSERT_NE(extra, nullptr) << space.label(a) << " step " << step;  // a disc turns in its body
          if (extra == nullptr) continue;
          const GridPose q = space.graph(a).pose(after(space, a, s, action));
          const CellSet both = space.cells(a).body(h).unionWith(space.cells(a).body(q.heading), {q.x - 20, q.y - 20});
          EXPECT_EQ(both.unionWith(*extra, {0, 0}), space.cells(a).swept(h, action)) << space.label(a);
          EXPECT_FALSE(CellSet::overlap(both, {0, 0}, *extra, {0, 0})) << space.label(a);
          if (a == 1 && (action == Action::Forward || action == Action::Backward)) EXPECT_TRUE(extra->empty());
        }
        EXPECT_EQ(space.moveExtra(a, h, Action::Wait), nullptr);
      }
    }
  }
}

// A disc waits alike at every heading, a block symmetric about its centre at opposite headings,
// a robot with a nose only at its own: the headings that share a wait have the same cells.
TEST(ContactProbeSearch, HeadingsThatShareAWaitHaveTheSameCells) {
  const World w(freeMap(40, 40), largeRobots());
  const SearchSpace space(allRobots(w));
  for (int a = 0; a < space.numAgents(); ++a) {
    for (int h = 0; h < kHeadings; ++h) {
      const int same = space.sameWaitHeading(a, h);
      EXPECT_LE(same, h);
      EXPECT_EQ(space.cells(a).body(same), space.cells(a).body(h)) << space.label(a);
    }
  }
  EXPECT_EQ(space.sameWaitHeading(0, 3), 0);  // the disc
  EXPECT_EQ(space.sameWaitHeading(1, 1), 0);  // the block: +x and -x
  EXPECT_EQ(space.sameWaitHeading(1, 3), 2);  // +y and -y
  EXPECT_EQ(space.sameWaitHeading(1, 2), 2);
  EXPECT_EQ(space.sameWaitHeading(2, 1), 1);  // the nose
}

// So a move's unsafe steps are those of its two bodies and of its extra cells: on random walks,
// the union of the three answers the soft path table's query on the move itself.
TEST(ContactProbeSearch, AMovesUnsafeStepsAreItsBodiesAndItsExtraCells) {
  const World w(freeMap(40, 40), largeRobots());
  const SearchSpace space(allRobots(w));
  Rng rng(5);
  int unsafe_seen = 0;
  auto steps = [](const std::vector<std::pair<int, int>>& runs, int forever, int until) {
    std::set<int> out;
    for (int t = 0; t <= until; ++t) {
      const bool in = t >= forever ||
                      std::any_of(runs.begin(), runs.end(), [t](const auto& r) { return r.first <= t && t <= r.second; });
      if (in) out.insert(t);
    }
    return out;
  };
  for (int round = 0; round < 150; ++round) {
    SoftPathTable table(space);
    std::vector<StatePath> walks = walksInto(table, space, rng);
    const int a = static_cast<int>(rng.uniformInt(0, space.numAgents() - 1));
    const StateId s = somewhere(space, a, walks, rng);
    const GridPose p = space.graph(a).pose(s);
    const int from = static_cast<int>(rng.uniformInt(0, 3));
    const int until = table.lastMove() + 2;
    for (Action action : {Action::Forward, Action::RotateCcw, Action::RotateCw}) {
      const StateId next = after(space, a, s, action);
      const CellSet* extra = space.moveExtra(a, p.heading, action);
      if (next == kNoState || !space.allows(a, s, action) || extra == nullptr) continue;
      std::vector<std::pair<int, int>> move, parts, runs;
      int move_forever = SoftPathTable::kNever, forever = SoftPathTable::kNever, f = SoftPathTable::kNever;
      table.unsafeRuns(a, s, action, move, move_forever, from);
      for (StateId body : {s, next}) {
        table.unsafeRuns(a, body, Action::Wait, runs, f, from);
        parts.insert(parts.end(), runs.begin(), runs.end());
        forever = std::min(forever, f);
      }
      table.spansAt(a, *extra, {p.x, p.y}, parts, forever, from);
      const std::set<int> expected = steps(move, move_forever, until);
      ASSERT_EQ(steps(parts, forever, until), expected) << "round " << round << ", " << space.label(a);
      unsafe_seen += static_cast<int>(expected.size());
    }
  }
  EXPECT_GT(unsafe_seen, 30);
}

// The robots met standing for good (collisionsAtEnd) are those met at the step after every
// move (collisions), after paths are inserted, removed and inserted again.
TEST(ContactProbeSearch, EndQueriesAgreeWithStepQueries) {
  const World w(freeMap(40, 40), largeRobots());
  const SearchSpace space(allRobots(w));
  Rng rng(7);
  int met_seen = 0;
  for (int round = 0; round < 100; ++round) {
    SoftPathTable table(space);
    std::vector<StatePath> walks = walksInto(table, space, rng);
    for (int a = 0; a < space.numAgents(); a += 2) {  // moved: their old ends must be forgotten
      table.remove(a);
      walks[a] = randomWalk(space, a, static_cast<int>(rng.uniformInt(0, 10)), rng);
      table.insert(a, walks[a]);
    }
    const int a = static_cast<int>(rng.uniformInt(0, space.numAgents() - 1));
    for (int k = 0; k < 20; ++k) {
      const StateId s = somewhere(space, a, walks, rng);
      for (int act = 0; act < kActions; ++act) {
        const Action action = static_cast<Action>(act);
        if (!space.allows(a, s, action)) continue;
        std::vector<int> at_end, at_step;
        table.collisionsAtEnd(a, s, action, at_end);
        table.collisions(a, s, action, table.lastMove() + 1, at_step);
        std::sort(at_end.begin(), at_end.end());
        std::sort(at_step.begin(), at_step.end());
        ASSERT_EQ(at_end, at_step) << "round " << round << ", " << space.label(a);
        met_seen += static_cast<int>(at_end.size());
      }
    }
  }
  EXPECT_GT(met_seen, 30);
}

// The reservation table asked with a probe answers as asked with the sweep: the other robots'
// walks are moving obstacles of the wide block's subproblem.
TEST(ContactProbeSearch, ReservationsFindEveryContact) {
  const World w(freeMap(40, 40), largeRobots());
  const SearchSpace all(allRobots(w));
  Rng rng(9);
  int taken_seen = 0;
  for (int round = 0; round < 150; ++round) {
    std::vector<StatePath> walks;
    Subproblem sub = allRobots(w);
    const int planned = 3;
    sub.robots = {planned};
    for (int b = 0; b < all.numAgents(); ++b) {
      walks.push_back(randomWalk(all, b, static_cast<int>(rng.uniformInt(0, 10)), rng));
      if (b == planned) continue;
      MovingObstacle m;
      m.robot = b;
      for (StateId q : walks.back()) m.path.push_back(all.graph(b).pose(q));
      sub.moving.push_back(m);
    }
    const SearchSpace space(sub);
    const ReservationTable& reservations = space.reservations();
    const StateId s = somewhere(all, planned, walks, rng);
    const GridPose p = space.graph(0).pose(s);
    for (int act = 0; act < kActions; ++act) {
      const Action action = static_cast<Action>(act);
      const CellSet& sweep = space.cells(0).swept(p.heading, action);
      const CellSet& probe = space.probe(0, p.heading, action);
      ASSERT_LT(probe.size(), sweep.size());
      EXPECT_EQ(reservations.lastTaken(probe, {p.x, p.y}), reservations.lastTaken(sweep, {p.x, p.y}));
      std::vector<std::pair<int, int>> by_probe, by_sweep;
      reservations.takenIntervals(probe, {p.x, p.y}, by_probe);
      reservations.takenIntervals(sweep, {p.x, p.y}, by_sweep);
      auto steps = [&](const std::vector<std::pair<int, int>>& runs) {
        std::set<int> out;
        for (const auto& [first, last] : runs)
          for (int t = first; t <= std::min(last, reservations.lastChange() + 1); ++t) out.insert(t);
        return out;
      };
      EXPECT_EQ(steps(by_probe), steps(by_sweep));
      for (int t = 0; t <= reservations.lastChange() + 1; ++t) {
        const bool taken = reservations.taken(sweep, {p.x, p.y}, t);
        ASSERT_EQ(reservations.taken(probe, {p.x, p.y}, t), taken) << "round " << round << ", step " << t;
        taken_seen += taken ? 1 : 0;
      }
    }
  }
  EXPECT_GT(taken_seen, 30);
}

}  // namespace
}  // namespace fleet_planner::test
