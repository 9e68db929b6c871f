#pragma once
/// Generated instances without the impossibilities the planner can prove (issue: scale must be
/// measured on instances that have a plan). The paper's generator draws each robot's start and
/// target alone, so two wide robots may block each other for good (one's target in the only
/// corridor the other must cross): such instances are INFEASIBLE for every planner. Here, after
/// generateInstance, every pair the decomposition finds entangled is decided by the pair proof
/// (infeasible_pairs.h, decidePair); a robot of each pair that is not shown possible
/// (proven impossible, or undecided within the budget) is drawn again (footprint kept; a robot
/// in several such pairs once for all of them), and the check repeats until every entangled
/// pair is shown possible. The decomposition's entangled pairs include every pair that cannot
/// both reach their targets alone (decomposition.h), so no two robots of a clean instance block
/// each other for good; larger groups are not checked.
#include <string>
#include <vector>

#include "fleet_planner/infeasibility/infeasible_pairs.h"
#include "fleet_planner/io/instance_generator.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/runtime/deadline.h"

namespace fleet_planner {

/// LA-LaCAM expansions of each pair proof of the check: pairs along a map's edge that only one
/// of the two can pass take 2-3 million to decide on the 256 x 256 city maps.
constexpr long long kGeneratorPairExpansions = 4'000'000;

struct FeasibleGeneration {
  Instance instance;
  int rounds = 0;                   ///< checks made (1: the first draw had no proven pair)
  std::vector<std::string> redrawn;  ///< "robot '7' (with '12'): <the proof's message>", in order
  bool clean = false;               ///< the last check showed every pair possible (false: rounds or time ran out)
};

/// A robot to draw again, the other robot of its first pair not shown possible, and why.
struct PairToRedraw {
  int robot = -1;
  int other = -1;
  std::string why;
};

/// One check of the generator: robots to draw again so that each of `pairs` (instance indices)
/// that decidePair (with `pair_expansions` and `backward_configurations`) does not show
/// possible loses one of its robots, the robot in most such pairs first (ties: the higher
/// index). Pairs left when the deadline passes are not decided.
std::vector<PairToRedraw> pairsToRedraw(const Instance& instance, const FleetGraphs& graphs,
                                        const std::vector<std::pair<int, int>>& pairs, long long pair_expansions,
                                        const Deadline& deadline,
                                        long long backward_configurations = kPairBackwardConfigurations);

/// generateInstance(map, options) with the check above, at most `max_rounds` checks; each pair
/// proof stops after `pair_expansions`. Deterministic when the deadline does not cut in. Throws
/// InvalidInput like generateInstance, and when a robot cannot be drawn again.
FeasibleGeneration generateFeasibleInstance(const GridMap& map, const GeneratorOptions& options, int max_rounds = 10,
                                            long long pair_expansions = kGeneratorPairExpansions, const Deadline& deadline = {});

}  // namespace fleet_planner
