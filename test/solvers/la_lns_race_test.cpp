// LA-LNS's race of two searches on two threads (LaLnsOptions::portfolio_robots): the rule that
// decides the winner, and whole solves that must give the same valid plan every time whichever
// thread runs faster.
#include <gtest/gtest.h>

#include <cstdint>
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
// first plan collides, so the repairs race on two threads.
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

std::vector<Path> solvePackedRoom(const World& w, std::uint64_t seed, bool race) {
  LaLnsOptions options;
  options.parking_expansions = 0;  // the soft first plan: collisions to repair
  options.portfolio_robots = race ? 2 : 0;
  LaLns solver(options);
  Subproblem sub = allRobots(w, 30.0, seed);
  sub.threads = 2;
  const Outcome o = solveWith(solver, w, sub);
  EXPECT_TRUE(solvedValidly(o)) << describe(o);
  return o.result.paths;
}

// Three raced solves give one plan, whichever thread runs faster. With seed 1 the first search
// wins: the plan is the lone search's. With seed 5 the second search gets there in fewer
// repairs: the plan is another one, and it is the same every time too.
TEST(LnsRace, TwoThreadsGiveTheSamePlanEveryTime) {
  const World w = packedRoom();
  for (const auto& [seed, second_wins] : {std::pair<std::uint64_t, bool>{1, false}, {5, true}}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const std::vector<Path> raced = solvePackedRoom(w, seed, true);
    for (int run = 1; run < 3; ++run) EXPECT_EQ(solvePackedRoom(w, seed, true), raced) << "run " << run;
    EXPECT_EQ(solvePackedRoom(w, seed, false) != raced, second_wins);
  }
}

}  // namespace
}  // namespace fleet_planner::test
