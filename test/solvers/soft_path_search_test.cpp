// LA-LNS's soft low level (soft_path_search.h) with a weighted heuristic: its paths cost at most
// `weight` times the cheapest, and it expands fewer nodes than the exact search. (On small maps
// the saving is small, 3-13 % in the fleets tried; it is large on long paths that wait, as in
// the packed levels of maze-128-128-10: docs/history.md.)
#include "fleet_planner/solvers/search/soft_path_search.h"

#include <gtest/gtest.h>

#include "fleet_planner/runtime/random.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

// One random step of agent b from s (waiting included).
StateId randomStep(const SearchSpace& space, int b, StateId s, Rng& rng) {
  std::vector<StateId> next{s};
  space.graph(b).forEachSuccessor(s, [&](Action act, StateId to) {
    if (space.allows(b, s, act)) next.push_back(to);
  });
  return next[rng.uniformInt(0, static_cast<std::int64_t>(next.size()) - 1)];
}

// Cost of a found path under the search's model: its steps plus collision_cost per collision.
long long costOf(const SoftSearchResult& r, int collision_cost) {
  return static_cast<long long>(r.path.size()) - 1 + static_cast<long long>(collision_cost) * r.collisions;
}

TEST(SoftPathSearch, WeightedPathsCostAtMostTheWeightTimesTheCheapest) {
  constexpr double kWeight = 1.5;
  long long exact_expansions = 0, weighted_expansions = 0;
  int searches = 0, dearer = 0;
  for (std::uint64_t seed = 0; seed < 12; ++seed) {
    const GridMap map = seed % 2 == 0 ? freeMap(24, 24) : freeMap(18, 32);
    const World w(map, generatedRobots(map, 14, seed));
    const Subproblem sub = allRobots(w);
    const SearchSpace space(sub);
    ASSERT_TRUE(space.problem().empty()) << space.problem();
    // Every agent but the last walks at random, stands still for a while and walks on: soft
    // obstacles that the last one must wait for or go around.
    Rng rng(seed);
    SoftPathTable table(space);
    const int n = space.numAgents(), a = n - 1;
    for (int b = 0; b < a; ++b) {
      StatePath path = randomWalk(space, b, static_cast<int>(rng.uniformInt(5, 20)), rng);
      path.insert(path.end(), static_cast<std::size_t>(rng.uniformInt(10, 40)), path.back());
      for (int t = 0; t < 20; ++t) path.push_back(randomStep(space, b, path.back(), rng));
      table.insert(b, path);
    }
    SoftSearchOptions exact, weighted;
    exact.max_expansions = weighted.max_expansions = 2'000'000;
    // A repeatedly colliding agent's cost (LA-LNS raises it up to 64 times): waiting is cheap.
    exact.collision_cost = weighted.collision_cost = 16 * 8;
    weighted.heuristic_weight = kWeight;
    const SoftSearchResult best = softPathSearch(space, a, table, Deadline(), exact);
    const SoftSearchResult r = softPathSearch(space, a, table, Deadline(), weighted);
    ASSERT_EQ(best.outcome, SoftSearchResult::Outcome::Found) << "seed " << seed;
    ASSERT_EQ(r.outcome, SoftSearchResult::Outcome::Found) << "seed " << seed;
    ASSERT_EQ(r.path.front(), space.start(a));
    ASSERT_EQ(r.path.back(), space.target(a));
    const long long cheapest = costOf(best, exact.collision_cost), cost = costOf(r, weighted.collision_cost);
    EXPECT_LE(cheapest, cost) << "seed " << seed;
    EXPECT_LE(static_cast<double>(cost), kWeight * static_cast<double>(cheapest)) << "seed " << seed;
    dearer += cost > cheapest;
    exact_expansions += best.expansions;
    weighted_expansions += r.expansions;
    ++searches;
  }
  EXPECT_EQ(searches, 12);
  EXPECT_LT(weighted_expansions, exact_expansions)
      << "weighted " << weighted_expansions << ", exact " << exact_expansions << " (" << dearer
      << " dearer paths)";
}

}  // namespace
}  // namespace fleet_planner::test
