// LA-LaCAM's configuration generator (la_pibt.h): every step it generates must be free of
// conflicts, checked pair by pair over the whole fleet.
#include <gtest/gtest.h>

#include <numeric>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/solvers/lacam/la_pibt.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "solver_test_util.h"
#include "test_maps.h"
#include "test_robots.h"

namespace fleet_planner::test {
namespace {

// `robots` generated robots on a free square map of `side` cells: their search space and starts.
struct Fleet {
  Fleet(int side, int robots, std::uint64_t seed)
      : world(freeMap(side, side), generatedRobots(freeMap(side, side), robots, seed)),
        sub(allRobots(world)),
        space(sub) {
    for (int a = 0; a < space.numAgents(); ++a) start.push_back(space.start(a));
  }
  World world;
  Subproblem sub;
  SearchSpace space;
  Config start;
};

TEST(LaPibt, GeneratedStepsHaveNoConflicts) {
  int moves = 0, near_pairs = 0;
  for (std::uint64_t seed = 0; seed < 6; ++seed) {
    const Fleet fleet(36, 40, seed);
    const SearchSpace& space = fleet.space;
    LaPibt pibt(space, seed);
    const int n = space.numAgents();
    Config current = fleet.start, next;
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    for (int step = 0; step < 60; ++step) {
      ASSERT_TRUE(pibt.generate(current, {}, order, next));
      std::vector<Action> act(n);
      for (int a = 0; a < n; ++a) {
        act[a] = stepAction(space.graph(a), current[a], next[a]);
        moves += act[a] != Action::Wait;
      }
      for (int a = 0; a < n; ++a) {
        const GridPose p = space.graph(a).pose(current[a]);
        for (int b = a + 1; b < n; ++b) {
          const GridPose q = space.graph(b).pose(current[b]);
          ASSERT_FALSE(sweepsOverlap(space.cells(a), p, act[a], space.cells(b), q, act[b]))
              << "seed " << seed << ", step " << step << ": agents " << a << " and " << b;
          // Agents near each other are what the cell claims must not miss.
          near_pairs += std::abs(p.x - q.x) + std::abs(p.y - q.y) <= 4;
        }
      }
      current = next;
    }
  }
  EXPECT_GT(moves, 1000);
  EXPECT_GT(near_pairs, 100);
}

// The escapes a pushed agent takes are remembered by (agent, state, pusher, pusher's state and
// action): on a packed fleet, with a new priority order every step, the generator must make the
// same steps as one that searches every escape afresh.
TEST(LaPibt, RememberedEscapesGiveTheSameStepsAsFreshSearches) {
  int differing_orders = 0, moves = 0;
  for (std::uint64_t seed = 0; seed < 4; ++seed) {
    const Fleet fleet(28, 30, seed);
    const SearchSpace& space = fleet.space;
    LaPibt remembering(space, seed), fresh(space, seed, /*remember_escapes=*/false);
    const int n = space.numAgents();
    Config current = fleet.start, next, expected;
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    Rng shuffle(seed);
    for (int step = 0; step < 150; ++step) {
      for (int i = n - 1; i > 0; --i) std::swap(order[i], order[shuffle.uniformInt(0, i)]);
      ASSERT_TRUE(fresh.generate(current, {}, order, expected));
      ASSERT_TRUE(remembering.generate(current, {}, order, next));
      ASSERT_EQ(next, expected) << "seed " << seed << ", step " << step;
      for (int a = 0; a < n; ++a) moves += next[a] != current[a];
      differing_orders += order.front() != 0;
      // Now and then back to the start, so that the same situations come again.
      current = next;
      if (step % 25 == 24) {
        current = fleet.start;
      }
    }
  }
  EXPECT_GT(moves, 1000);
  EXPECT_GT(differing_orders, 100);
}

// The footprints the generator has placed on the map are moved from one configuration to the
// next, as LA-LaCAM jumps between the configurations it has made: it must make the same steps
// as a new generator (footprints placed afresh) given the same random state.
TEST(LaPibt, AGeneratorKeptAcrossConfigurationsGivesTheSameStepsAsANewOne) {
  int moves = 0, jumps = 0;
  for (std::uint64_t seed = 0; seed < 4; ++seed) {
    const Fleet fleet(40, 40, seed);
    const SearchSpace& space = fleet.space;
    LaPibt kept(space, seed);
    const int n = space.numAgents();
    Config next, expected;
    std::vector<Config> made{fleet.start};
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    Rng pick(seed);
    for (int step = 0; step < 200; ++step) {
      // Mostly from the newest configuration, now and then from an earlier one.
      const bool jump = pick.uniformInt(0, 3) == 0;
      const Config& current = jump ? made[pick.uniformInt(0, made.size() - 1)] : made.back();
      jumps += jump;
      for (int i = n - 1; i > 0; --i) std::swap(order[i], order[pick.uniformInt(0, i)]);
      LaPibt fresh(space, seed);
      fresh.rng() = kept.rng();
      ASSERT_TRUE(fresh.generate(current, {}, order, expected));
      ASSERT_TRUE(kept.generate(current, {}, order, next));
      ASSERT_EQ(next, expected) << "seed " << seed << ", step " << step;
      for (int a = 0; a < n; ++a) moves += next[a] != current[a];
      made.push_back(next);
    }
  }
  EXPECT_GT(moves, 1000);
  EXPECT_GT(jumps, 100);
}

// An agent at its target, not pushed, waits without ranking its candidates, yet takes one
// random draw per candidate as ranking them would: the random stream, and so every later
// choice of the search, stays what it was.
TEST(LaPibt, AnAgentAtItsTargetWaitsAndTakesItsDraws) {
  for (std::uint64_t seed = 0; seed < 8; ++seed) {
    const GridPose here{5 + static_cast<int>(seed), 7, static_cast<int>(seed % kHeadings)};
    const World w(freeMap(20, 20), {dot("parked", here, here)});
    const SearchSpace space(allRobots(w));
    LaPibt pibt(space, seed);
    Config next;
    ASSERT_TRUE(pibt.generate({space.start(0)}, {}, {0}, next));
    EXPECT_EQ(next[0], space.start(0));
    int choices = 1;  // waiting, and every allowed move to a state with a distance
    space.graph(0).forEachSuccessor(space.start(0), [&](Action action, StateId s) {
      choices += space.distance(0, s) >= 0 && space.allows(0, space.start(0), action);
    });
    EXPECT_GT(choices, 2);
    Rng expected(seed);
    for (int i = 0; i < choices; ++i) expected.next();
    EXPECT_EQ(pibt.rng().next(), expected.next()) << "seed " << seed;
  }
}

// An agent whose best step is blocked by an agent that has already moved (here: stayed at its
// target) takes its next best in rank: waiting (as far from its target as now) before turning
// away (one step farther).
TEST(LaPibt, AnAgentWhoseBestStepIsBlockedTakesItsNextBest) {
  for (std::uint64_t seed = 0; seed < 8; ++seed) {
    const World w(freeMap(20, 20),
                  {dot("parked", {8, 7, 0}, {8, 7, 0}), dot("behind", {7, 7, 0}, {12, 7, 0})});
    const SearchSpace space(allRobots(w));
    LaPibt pibt(space, seed);
    const Config start = {space.start(0), space.start(1)};
    Config next;
    ASSERT_TRUE(pibt.generate(start, {}, {0, 1}, next));
    EXPECT_EQ(next[0], start[0]);
    EXPECT_EQ(next[1], start[1]) << "seed " << seed << ": waits rather than turning away";
  }
}

}  // namespace
}  // namespace fleet_planner::test
