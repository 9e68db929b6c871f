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

TEST(EndGame, DoesNotPlanTheSameGroupAgain) {
  // The corridor without a pocket: nobody else stands near the ways, so the rounds after the
  // first would add nobody to the group of the first. Its plan fails by the joint search's
  // proof, whatever the machine's speed: no time-bound repair (LA-CBS, LA-LaCAM, pair proofs)
  // comes before it.
  const World w(mapFromRows({"..............", "@@@@@@@@@@@@@@"}),
                {dot("a", {0, 0, 0}, {13, 0, 0}), dot("b", {13, 0, 2}, {0, 0, 2})});
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  LaLnsOptions lns;
  lns.joint_seconds = 0;
  lns.alone_expansions = 0;
  lns.pair_proof_expansions = 0;
  ASSERT_EQ(LaLns(lns).solve(allRobots(w, 60.0)).status, SolveStatus::Infeasible);
  const std::vector<StatePath> parked = {{space.start(0)}, {space.start(1)}};
  auto spent = [&](int rounds) {
    EndGameOptions options;
    options.rounds = rounds;
    long long expansions = 0;
    EXPECT_FALSE(endGame(space, sub, parked, {0, 0}, lns, Deadline::in(60.0), options, expansions).has_value());
    return expansions;
  };
  const long long one_round = spent(1);
  EXPECT_GT(one_round, 0);
  EXPECT_EQ(spent(EndGameOptions{}.rounds), one_round);
}

TEST(EndGame, TakesTheWayHomeThroughFewestStandingRobots) {
  // Two streets: "a" left on the short one would pass b and c, parked at their targets there;
  // the long one is empty. Only a is to move.
  const World w(mapFromRows({"...........", ".@@@@@@@@@.", "..........."}),
                {dot("a", {0, 0, 0}, {10, 0, 0}), dot("b", {4, 0, 0}, {4, 0, 0}),
                 dot("c", {7, 0, 0}, {7, 0, 0})});
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  const std::vector<StatePath> parked = {{space.start(0)}, {space.start(1)}, {space.start(2)}};
  EndGameOptions options;
  options.max_group = 2;  // a, b and c together are too many
  long long expansions = 0;
  const auto done = endGame(space, sub, parked, {0, 1, 1}, LaLnsOptions{}, Deadline::in(5.0), options, expansions);
  ASSERT_TRUE(done.has_value());
  const std::vector<StatePath>& paths = *done;
  EXPECT_EQ(paths[0].back(), space.target(0));
  EXPECT_EQ(paths[1], parked[1]) << "b stays parked";
  EXPECT_EQ(paths[2], parked[2]) << "c stays parked";
  const ValidationResult v = validateStatePaths(w, sub, space, paths);
  EXPECT_TRUE(v.valid()) << violationName(v.violation.kind);
}

TEST(EndGame, WidensTheGroupByTheNearestRobotsUpToItsSize) {
  // "a" must pass b in a corridor; b's only pocket, two cells deep, holds c (parked at its
  // target at the pocket's mouth). d and e stand on a lane behind a wall, four rows away.
  // The first group (a, b) has no plan; the next takes c, the nearest, and not d and e,
  // which would make five robots where three are allowed.
  const World w(mapFromRows({"..............", "@@@@@@.@@@@@@@", "@@@@@@.@@@@@@@", "@@@@@@@@@@@@@@",
                             ".............."}),
                {dot("a", {0, 0, 0}, {13, 0, 0}), dot("b", {9, 0, 0}, {9, 0, 0}),
                 dot("c", {6, 1, 2}, {6, 1, 2}), dot("d", {2, 4, 0}, {2, 4, 0}),
                 dot("e", {12, 4, 0}, {12, 4, 0})});
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  std::vector<StatePath> parked;
  for (int a = 0; a < 5; ++a) parked.push_back({space.start(a)});
  EndGameOptions options;
  options.max_group = 3;
  long long expansions = 0;
  const auto done =
      endGame(space, sub, parked, {0, 1, 1, 1, 1}, LaLnsOptions{}, Deadline::in(5.0), options, expansions);
  ASSERT_TRUE(done.has_value());
  const std::vector<StatePath>& paths = *done;
  for (int a = 0; a < 3; ++a) EXPECT_EQ(paths[a].back(), space.target(a)) << a;
  EXPECT_GT(paths[2].size(), 1u) << "c made way";
  EXPECT_EQ(paths[3], parked[3]) << "d stays";
  EXPECT_EQ(paths[4], parked[4]) << "e stays";
  const ValidationResult v = validateStatePaths(w, sub, space, paths);
  EXPECT_TRUE(v.valid()) << violationName(v.violation.kind);
}

}  // namespace
}  // namespace fleet_planner::test
