// Generated instances without impossible pairs: on a map of narrow corridors the paper's
// generator draws pairs of robots that cannot both reach their targets; --feasible draws them
// again, and the pairs the pair proof leaves undecided too, until every entangled pair is shown
// possible.
#include <gtest/gtest.h>

#include "fleet_planner/decomposition/decomposition.h"
#include "fleet_planner/infeasibility/feasible_instances.h"
#include "fleet_planner/infeasibility/infeasible_pairs.h"
#include "test_maps.h"
#include "test_robots.h"

namespace fleet_planner::test {
namespace {

// Corridors two cells wide with dead ends: wide robots parked in them block each other.
GridMap corridors() {
  return mapFromRows({"..............",
                      "..............",
                      "..@@@@..@@@@..",
                      "..@@@@..@@@@..",
                      "..@@@@..@@@@..",
                      "..............",
                      "..............",
                      "..@@@@@@@@..@@",
                      "..@@@@@@@@..@@",
                      "..............",
                      ".............."});
}

// The first pair of the decomposition's entangled pairs that the pair proof rejects, if any.
std::optional<std::string> provenPair(const GridMap& map, const Instance& instance) {
  const FleetGraphs graphs(map, footprintsOf(instance));
  const Decomposition d = decompose(instance, graphs, DecompositionOptions{});
  return findInfeasiblePair(instance, graphs, d.entangled_pairs, 500'000, Deadline{});
}

TEST(FeasibleInstances, ProvenPairsAreDrawnAgainUntilNoneIsLeft) {
  const GridMap map = corridors();
  GeneratorOptions o;
  o.robots = 6;
  o.max_size = 1.0;
  int with_proof = 0;
  for (std::uint64_t seed = 0; seed < 40 && with_proof < 3; ++seed) {
    o.seed = seed;
    Instance plain;
    try {
      plain = generateInstance(map, o);
    } catch (const InvalidInput&) {
      continue;  // no room for this draw
    }
    if (!provenPair(map, plain)) continue;
    ++with_proof;
    const FeasibleGeneration g = generateFeasibleInstance(map, o);
    EXPECT_TRUE(g.clean) << "seed " << seed;
    EXPECT_FALSE(g.redrawn.empty()) << "seed " << seed;
    EXPECT_FALSE(provenPair(map, g.instance)) << "seed " << seed;
    ASSERT_EQ(g.instance.robots.size(), plain.robots.size());
    for (std::size_t i = 0; i < plain.robots.size(); ++i) {
      EXPECT_EQ(g.instance.robots[i].footprint.describe(), plain.robots[i].footprint.describe());
    }
    const FeasibleGeneration again = generateFeasibleInstance(map, o);
    EXPECT_EQ(again.redrawn, g.redrawn);
    for (std::size_t i = 0; i < plain.robots.size(); ++i) {
      EXPECT_EQ(again.instance.robots[i].start, g.instance.robots[i].start);
      EXPECT_EQ(again.instance.robots[i].target, g.instance.robots[i].target);
    }
  }
  EXPECT_GT(with_proof, 0) << "no seed drew a proven pair: the test checks nothing";
}

// Two one-cell robots trading the ends of a one-wide corridor: neither can go first, so the
// pair is decided only by a search of both together. With a pocket halfway the pair is
// possible, but a budget of ten expansions forwards and twenty configurations backwards leaves
// it undecided: it is drawn again all the same.
// Without the pocket it is impossible.
TEST(FeasibleInstances, APairNotShownPossibleIsDrawnAgainAsWellAsAnImpossibleOne) {
  const std::vector<std::pair<int, int>> pair{{0, 1}};
  auto check = [&](const GridMap& map, long long expansions) {
    Instance in;
    in.robots = {dot("a", {0, 0, 0}, {13, 0, 0}), dot("b", {13, 0, 1}, {0, 0, 1})};
    const FleetGraphs graphs(map, footprintsOf(in));
    return pairsToRedraw(in, graphs, pair, expansions, Deadline::in(30.0), 2 * expansions);
  };
  const GridMap pocket = mapFromRows({"..............", "@@@@@@.@@@@@@@"});
  EXPECT_TRUE(check(pocket, 500'000).empty()) << "shown possible: kept";
  const std::vector<PairToRedraw> undecided = check(pocket, 10);
  ASSERT_EQ(undecided.size(), 1u);
  EXPECT_EQ(undecided[0].robot, 1);
  EXPECT_EQ(undecided[0].other, 0);
  EXPECT_NE(undecided[0].why.find("not shown able"), std::string::npos) << undecided[0].why;
  const std::vector<PairToRedraw> impossible = check(mapFromRows({"..............", "@@@@@@@@@@@@@@"}), 500'000);
  ASSERT_EQ(impossible.size(), 1u);
  EXPECT_EQ(impossible[0].robot, 1);
  EXPECT_NE(impossible[0].why.find("cannot both reach their targets"), std::string::npos) << impossible[0].why;
}

// On a one-wide line, "x" drives west past "a" and "b", which drive east one behind the other:
// x cannot reach its target with either of them, a and b can with each other. x alone is drawn
// again, though it is the first of both pairs (the second robot of each pair was drawn before,
// a and b both).
TEST(FeasibleInstances, ARobotInSeveralImpossiblePairsIsDrawnAgainOnce) {
  const GridMap line = mapFromRows({"............"});
  Instance in;
  in.robots = {dot("x", {11, 0, 1}, {2, 0, 1}), dot("a", {0, 0, 0}, {9, 0, 0}), dot("b", {1, 0, 0}, {10, 0, 0})};
  const FleetGraphs graphs(line, footprintsOf(in));
  const std::vector<PairToRedraw> redraw = pairsToRedraw(in, graphs, {{0, 1}, {0, 2}, {1, 2}}, 500'000, Deadline::in(30.0));
  ASSERT_EQ(redraw.size(), 1u);
  EXPECT_EQ(redraw[0].robot, 0);
  EXPECT_EQ(redraw[0].other, 1);
  EXPECT_NE(redraw[0].why.find("cannot both reach their targets"), std::string::npos) << redraw[0].why;
}

}  // namespace
}  // namespace fleet_planner::test
