// The end of a parking plan (end_game.h): the robots it left and those on their ways, planned
// together once everybody else has stopped. Every plan passes the validator.
#include "fleet_planner/solvers/lns/end_game.h"

#include <gtest/gtest.h>

#include "fleet_planner/solvers/lns/la_lns.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

// A corridor 14 cells long with a pocket below x = 6, and, behind a wall, a lane of its own:
// "a" drives the corridor east past "b", who stands at its target at x = 9; "c" drives its lane.
World corridorAndLane() {
  return World(mapFromRows({"..............", "@@@@@@.@@@@@@@", "@@@@@@@@@@@@@@", ".............."}),
               {dot("a", {0, 0, 0}, {13, 0, 0}), dot("b", {9, 0, 0}, {9, 0, 0}),
                dot("c", {0, 3, 0}, {13, 3, 0})});
}

std::optional<std::vector<StatePath>> finish(const SearchSpace& space, const Subproblem& sub,
                                             const std::vector<StatePath>& paths,
                                             const std::vector<char>& home) {
  long long expansions = 0;
  return endGame(space, sub, paths, home, LaLnsOptions{}, Deadline::in(5.0), EndGameOptions{},
                 expansions);
}

TEST(EndGame, PlansTheRobotLeftWithTheRobotOnItsWayAfterEverybodyHasStopped) {
  const World w = corridorAndLane();
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  const LowLevelResult lane = spaceTimeAStar(space, 2, AgentConstraints{}, Deadline::in(5.0));
  ASSERT_EQ(lane.outcome, LowLevelResult::Outcome::Found);
  // "a" was left at its start; b and c are home, c after driving its lane.
  const std::vector<StatePath> parked = {{space.start(0)}, {space.start(1)}, lane.path};
  const auto done = finish(space, sub, parked, {0, 1, 1});
  ASSERT_TRUE(done.has_value());
  const std::vector<StatePath>& paths = *done;
  EXPECT_EQ(paths[0].back(), space.target(0));
  EXPECT_EQ(paths[1].back(), space.target(1));
  EXPECT_EQ(paths[2], lane.path) << "c is not on a's way: its path stays";
  EXPECT_GT(paths[1].size(), 1u) << "b had to make way";
  // a waits at its start until c has stopped.
  for (std::size_t t = 0; t + 1 < lane.path.size(); ++t) EXPECT_EQ(paths[0][t], space.start(0));
  const ValidationResult v = validateStatePaths(w, sub, space, paths);
  EXPECT_TRUE(v.valid()) << violationName(v.violation.kind);
  EXPECT_EQ(finish(space, sub, parked, {0, 1, 1}), done) << "same input, same plan";
}

TEST(EndGame, KeepsWithinTheCallersExpansionBudget) {
  const World w = corridorAndLane();
  Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  const std::vector<StatePath> parked = {{space.start(0)}, {space.start(1)}, {space.start(2)}};
  const std::vector<char> home = {0, 1, 0};
  sub.max_expansions = 1000;
  long long spent = 1000;  // all of it spent before the end game
  EXPECT_FALSE(endGame(space, sub, parked, home, LaLnsOptions{}, Deadline::in(5.0), EndGameOptions{}, spent)
                   .has_value());
  spent = 0;
  EXPECT_TRUE(endGame(space, sub, parked, home, LaLnsOptions{}, Deadline::in(5.0), EndGameOptions{}, spent)
                  .has_value());
  EXPECT_GT(spent, 0);
  EXPECT_LE(spent, 1000 + 1000) << "the group's search stops near the budget";
}

TEST(EndGame, AnswersNoneWhereTheRobotsLeftCannotPass) {
  // Two robots trading the ends of a corridor without a pocket.
  const World w(mapFromRows({"..............", "@@@@@@@@@@@@@@"}),
                {dot("a", {0, 0, 0}, {13, 0, 0}), dot("b", {13, 0, 2}, {0, 0, 2})});
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  EXPECT_FALSE(finish(space, sub, {{space.start(0)}, {space.start(1)}}, {0, 0}).has_value());
}

}  // namespace
}  // namespace fleet_planner::test
