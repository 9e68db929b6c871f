// LA-LNS's race of two searches on two threads (LaLnsOptions::portfolio_robots): the rule that
// decides the winner, and whole solves that must give the same valid plan every time whichever
// thread runs faster.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "fleet_planner/runtime/random.h"
#include "fleet_planner/solvers/lns/la_lns.h"
#include "fleet_planner/solvers/lns/lns_race.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

// The outcome after fewer repairs wins, ties to search 0; a search is beaten only by an outcome
// it can no longer reach first.
TEST(LnsRace, FewerRepairsWinTiesGoToTheFirstSearch) {
  LnsRace race;
  EXPECT_FALSE(race.beaten(0, 5));
  EXPECT_FALSE(race.beaten(1, 5));
  race.outcome_at[1] = 7;  // search 1 reached its outcome after 7 repairs
  EXPECT_FALSE(race.beaten(0, 6));
  EXPECT_FALSE(race.beaten(0, 7)) << "a tie goes to search 0";
  EXPECT_TRUE(race.beaten(0, 8));
  race.outcome_at[1] = LnsRace::kNone;
  race.outcome_at[0] = 7;
  EXPECT_FALSE(race.beaten(1, 6));
  EXPECT_TRUE(race.beaten(1, 7)) << "a tie goes to search 0";
  EXPECT_TRUE(race.beaten(1, 8));
}

// A packed room: 24 dots on a 10 x 10 map with pillars, each to another robot's start. The soft
// first plan collides, so the repairs race on two threads. Five solves give one plan, valid each
// time; the second search's work shows in the expansions (a solve without the race makes fewer).
World packedRoom() {
  const std::vector<std::string> rows{"..........", "..........", "..@....@..", "..........",
                                      "....@@....", "....@@....", "..........", "..@....@..",
                                      "..........", ".........."};
  GridMap map = mapFromRows(rows);
  std::vector<GridPose> free;
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x)
      if (rows[y][x] == '.') free.push_back({x, y, 0});
  Rng rng(7);
  for (std::size_t i = free.size(); i > 1; --i)
    std::swap(free[i - 1], free[rng.uniformInt(0, i - 1)]);
  std::vector<Robot> robots;
  const int n = 24;
  for (int i = 0; i < n; ++i)
    robots.push_back(dot("r" + std::to_string(i), free[i], free[(i + 5) % n]));
  return World(std::move(map), std::move(robots));
}

TEST(LnsRace, TwoThreadsGiveTheSamePlanEveryTime) {
  const World w = packedRoom();
  LaLnsOptions options;
  options.parking_expansions = 0;  // the soft first plan: collisions to repair
  options.portfolio_robots = 2;
  std::vector<Path> first;
  long long raced = 0;
  for (int run = 0; run < 5; ++run) {
    SCOPED_TRACE("run " + std::to_string(run));
    LaLns solver(options);
    Subproblem sub = allRobots(w, 30.0);
    sub.threads = 2;
    const Outcome o = solveWith(solver, w, sub);
    ASSERT_TRUE(solvedValidly(o)) << describe(o);
    if (run == 0) {
      first = o.result.paths;
      raced = o.result.stats.low_level_expansions;
    } else {
      EXPECT_EQ(o.result.paths, first);
    }
  }
  options.portfolio_robots = 0;
  LaLns alone(options);
  Subproblem sub = allRobots(w, 30.0);
  sub.threads = 2;
  const Outcome o = solveWith(alone, w, sub);
  ASSERT_TRUE(solvedValidly(o)) << describe(o);
  EXPECT_GT(raced, o.result.stats.low_level_expansions) << "the second search did not run";
}

}  // namespace
}  // namespace fleet_planner::test
