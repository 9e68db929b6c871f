// Generated instances without proven impossibilities: on a map of narrow corridors the paper's
// generator draws pairs of robots that cannot both reach their targets; --feasible draws them
// again until the pair proofs find none.
#include <gtest/gtest.h>

#include "fleet_planner/decomposition/decomposition.h"
#include "fleet_planner/infeasibility/feasible_instances.h"
#include "fleet_planner/infeasibility/infeasible_pairs.h"
#include "test_maps.h"

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

std::vector<Footprint> footprintsOf(const Instance& instance) {
  std::vector<Footprint> out;
  for (const Robot& r : instance.robots) out.push_back(r.footprint);
  return out;
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

}  // namespace
}  // namespace fleet_planner::test
