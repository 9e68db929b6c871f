// What the searches keep and skip when they look up the other robots (safe_interval_search.cpp,
// soft_path_table.h, the parking plan's crowds): each shortcut answers as the full lookup does.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <tuple>
#include <vector>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/solvers/search/safe_interval_search.h"
#include "fleet_planner/solvers/search/soft_path_table.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "large_robot_walks.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

// The same for the robots standing for good that a move meets (collisionsAtEnd): those its two
// bodies meet and those its extra cells meet.
TEST(SearchLookups, ARobotStandingOnAMoveStandsOnItsBodiesOrItsExtraCells) {
  const World w(freeMap(40, 40), largeRobots());
  const SearchSpace space(allRobots(w));
  Rng rng(6);
  int met_seen = 0;
  for (int round = 0; round < 150; ++round) {
    SoftPathTable table(space);
    std::vector<StatePath> walks = walksInto(table, space, rng);
    const int a = static_cast<int>(rng.uniformInt(0, space.numAgents() - 1));
    const StateId s = somewhere(space, a, walks, rng);
    const GridPose p = space.graph(a).pose(s);
    for (Action action : {Action::Forward, Action::Backward, Action::RotateCcw, Action::RotateCw}) {
      const StateId next = after(space, a, s, action);
      const CellSet* extra = space.moveExtra(a, p.heading, action);
      if (next == kNoState || !space.allows(a, s, action) || extra == nullptr) continue;
      std::vector<int> move, parts;
      table.collisionsAtEnd(a, s, action, move);
      table.collisionsAtEnd(a, s, Action::Wait, parts);
      table.collisionsAtEnd(a, next, Action::Wait, parts);
      table.collisionsAtEnd(a, *extra, {p.x, p.y}, parts);
      std::sort(move.begin(), move.end());
      std::sort(parts.begin(), parts.end());
      parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
      ASSERT_EQ(parts, move) << "round " << round << ", " << space.label(a);
      met_seen += static_cast<int>(move.size());
    }
  }
  EXPECT_GT(met_seen, 30);
}

// What the table keeps from its answers (each cell's steps, markUnsafe) follows the paths taken
// out and put in: after queries near the walks, some walks out and others in, it answers as a
// new table of the same walks.
TEST(SearchLookups, MarkedStepsFollowRemovals) {
  const World w(freeMap(40, 40), largeRobots());
  const SearchSpace space(allRobots(w));
  Rng rng(4);
  int differ = 0;
  for (int round = 0; round < 60; ++round) {
    const int a = static_cast<int>(rng.uniformInt(0, space.numAgents() - 1));
    SoftPathTable table(space);
    std::vector<StatePath> walks = walksInto(table, space, rng);
    table.remove(a);
    std::vector<StateId> asked;
    for (int k = 0; k < 20; ++k) asked.push_back(somewhere(space, a, walks, rng));
    auto answers = [&](const SoftPathTable& t) {
      std::vector<std::uint64_t> out;
      for (StateId s : asked) {
        std::vector<std::uint64_t> bits(static_cast<std::size_t>(t.lastMove() + 2) / 64 + 1, 0);
        int lo = SoftPathTable::kNever, hi = -1, forever = SoftPathTable::kNever;
        t.markUnsafe(a, s, Action::Wait, bits.data(), lo, hi, forever, 0);
        out.insert(out.end(), bits.begin(), bits.end());
        out.push_back(static_cast<std::uint64_t>(forever));
      }
      return out;
    };
    const std::vector<std::uint64_t> before = answers(table);
    for (int b = 0; b < space.numAgents(); ++b) {
      if (b == a || rng.uniformInt(0, 2) > 0) continue;
      table.remove(b);
      if (rng.uniformInt(0, 1) == 0) continue;
      walks[b] = randomWalk(space, b, static_cast<int>(rng.uniformInt(0, 10)), rng);
      table.insert(b, walks[b]);
    }
    SoftPathTable fresh(space);
    for (int b = 0; b < space.numAgents(); ++b) {
      if (table.contains(b)) fresh.insert(b, walks[b]);
    }
    const std::vector<std::uint64_t> after = answers(table);
    ASSERT_EQ(after, answers(fresh)) << "round " << round;
    differ += after != before ? 1 : 0;
  }
  EXPECT_GT(differ, 10);
}

// The same as walks grow: each path put in makes the horizon longer (up to 21 words of steps)
// after cells' steps have been kept for shorter ones; the kept steps widen and still answer as
// a new table's.
TEST(SearchLookups, MarkedStepsFollowAGrowingHorizon) {
  const World w(freeMap(40, 40), largeRobots());
  const SearchSpace space(allRobots(w));
  Rng rng(5);
  for (int round = 0; round < 10; ++round) {
    const int a = static_cast<int>(rng.uniformInt(0, space.numAgents() - 1));
    SoftPathTable table(space);
    std::vector<StatePath> walks;
    for (int b = 0; b < space.numAgents(); ++b)
      walks.push_back(randomWalk(space, b, 40 + 300 * b + static_cast<int>(rng.uniformInt(0, 60)), rng));
    std::vector<StateId> asked;
    int words_seen = 0;
    for (int b = 0; b < space.numAgents(); ++b) {
      if (b == a) continue;
      table.insert(b, walks[b]);
      for (int k = 0; k < 10; ++k) asked.push_back(somewhere(space, a, walks, rng));
      SoftPathTable fresh(space);
      for (int c = 0; c <= b; ++c) {
        if (c != a) fresh.insert(c, walks[c]);
      }
      for (StateId s : asked) {
        const std::size_t words = static_cast<std::size_t>(table.lastMove() + 2) / 64 + 1;
        std::vector<std::uint64_t> kept(words, 0), anew(words, 0);
        int lo = SoftPathTable::kNever, hi = -1, forever = SoftPathTable::kNever;
        int lo2 = lo, hi2 = hi, forever2 = forever;
        table.markUnsafe(a, s, Action::Wait, kept.data(), lo, hi, forever, 0);
        fresh.markUnsafe(a, s, Action::Wait, anew.data(), lo2, hi2, forever2, 0);
        ASSERT_EQ(kept, anew) << "round " << round << ", robot " << b;
        ASSERT_EQ(std::make_tuple(lo, hi, forever), std::make_tuple(lo2, hi2, forever2));
        words_seen = std::max(words_seen, hi < 0 ? 0 : hi / 64 + 1);
      }
    }
    EXPECT_GT(words_seen, 10) << "round " << round;
  }
}

// A turn and the opposite turn back from where it ends sweep the same cells wherever the search
// space says so (the safe interval search then asks the table once for both), and they meet
// the same robots there; it says so for most turns of the large robots, on lattices of 1 and 2.
TEST(SearchLookups, ATurnAndTheTurnBackMeetTheSameRobots) {
  for (int step = 1; step <= 2; ++step) {
    ActionModel model;
    model.step = step;
    const LargeRobotsOn scene(model);
    const SearchSpace& space = scene.space;
    int alike = 0, turns = 0;
    for (int a = 0; a < space.numAgents(); ++a) {
      for (int h = 0; h < kHeadings; ++h) {
        for (Action turn : {Action::RotateCcw, Action::RotateCw}) {
          ++turns;
          const int back_heading = turn == Action::RotateCcw ? kRotateCcw[h] : kRotateCw[h];
          const Action back = turn == Action::RotateCcw ? Action::RotateCw : Action::RotateCcw;
          const bool same = space.cells(a).swept(h, turn) == space.cells(a).swept(back_heading, back);
          ASSERT_EQ(space.turnsBackAlike(a, h, turn), same) << space.label(a) << " heading " << h;
          if (!same) continue;
          ++alike;
          ASSERT_EQ(space.probe(a, h, turn), space.probe(a, back_heading, back));
        }
      }
    }
    EXPECT_GT(alike, turns / 2) << "step " << step;
  }
}

// The safe interval search reads a move that decomposes from its extra cells alone, its bodies
// being those of the safe intervals it leaves and enters: it still arrives when space-time A*
// does, around the same random walks, whether they are in the soft path table or moving
// obstacles (reservations), for every robot shape; and a search asked again answers alike.
TEST(SearchLookups, SafeIntervalsArriveWhenSpaceTimeSearchDoes) {
  Rng rng(11);
  int delayed = 0, compared = 0;
  for (int round = 0; round < 400; ++round) {
    std::vector<Robot> robots = largeRobots();
    const int a = static_cast<int>(rng.uniformInt(0, static_cast<std::int64_t>(robots.size()) - 1));
    std::unique_ptr<World> w;
    auto anywhere = [&] {
      return GridPose{static_cast<int>(rng.uniformInt(6, 53)), static_cast<int>(rng.uniformInt(6, 53)),
                      static_cast<int>(rng.uniformInt(0, kHeadings - 1))};
    };
    while (!w) {  // a start and a target anywhere free, clear of the others' (their starts)
      robots[a].start = anywhere();
      robots[a].target = anywhere();
      try {
        w = std::make_unique<World>(freeMap(60, 60), robots);
      } catch (const InvalidInput&) {
      }
    }
    const SearchSpace all(allRobots(*w));
    SoftPathTable table(all);
    Subproblem alone = allRobots(*w);
    alone.robots = {a};
    Instance walked = w->instance;  // the others' targets where their walks end
    Plan plan;
    plan.paths.resize(robots.size());
    for (int b = 0; b < all.numAgents(); ++b) {
      if (b == a) continue;
      const StatePath walk = randomWalk(all, b, static_cast<int>(rng.uniformInt(5, 25)), rng);
      table.insert(b, walk);
      MovingObstacle m;
      m.robot = b;
      for (StateId s : walk) m.path.push_back(all.graph(b).pose(s));
      plan.paths[b] = m.path;
      walked.robots[b].target = m.path.back();
      alone.moving.push_back(m);
    }
    const SearchSpace moving(alone);
    const LowLevelResult best = spaceTimeAStar(moving, 0, AgentConstraints{}, Deadline::in(5.0));
    const SafeIntervalResult soft = safeIntervalSearch(all, a, table, Deadline::in(5.0), 1'000'000);
    const SafeIntervalResult reserved =
        safeIntervalSearch(moving, 0, SoftPathTable(moving), Deadline::in(5.0), 1'000'000);
    // Asked again after another search on this thread (which reuses its memory): the same.
    const SafeIntervalResult again = safeIntervalSearch(all, a, table, Deadline::in(5.0), 1'000'000);
    ASSERT_EQ(again.outcome, soft.outcome) << "round " << round;
    ASSERT_EQ(again.path, soft.path) << "round " << round;
    const bool found = best.outcome == LowLevelResult::Outcome::Found;
    ASSERT_EQ(soft.outcome == SafeIntervalResult::Outcome::Found, found) << "round " << round;
    ASSERT_EQ(reserved.outcome == SafeIntervalResult::Outcome::Found, found) << "round " << round;
    if (!found) continue;
    ASSERT_EQ(soft.path.size(), best.path.size()) << "round " << round << ", " << all.label(a);
    ASSERT_EQ(reserved.path.size(), best.path.size()) << "round " << round << ", " << all.label(a);
    for (StateId s : soft.path) plan.paths[a].push_back(all.graph(a).pose(s));
    // The walks may meet each other: only a's path and its conflicts are checked.
    const ValidationResult v = validatePlanChanges(w->map, walked, plan, ActionModel{}, {a});
    ASSERT_TRUE(v.valid()) << "round " << round << ": " << violationName(v.violation.kind);
    ++compared;
    delayed += static_cast<int>(best.path.size()) - 1 > all.distance(a, all.start(a)) ? 1 : 0;
  }
  EXPECT_GT(compared, 200);
  EXPECT_GT(delayed, 25);  // the walks were in the way
}

}  // namespace
}  // namespace fleet_planner::test
