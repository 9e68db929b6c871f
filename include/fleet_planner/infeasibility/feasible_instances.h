#pragma once
/// Generated instances without the impossibilities the planner can prove (issue: scale must be
/// measured on instances that have a plan). The paper's generator draws each robot's start and
/// target alone, so two wide robots may block each other for good (one's target in the only
/// corridor the other must cross): such instances are INFEASIBLE for every planner. Here, after
/// generateInstance, every pair the decomposition finds entangled is tried with the pair proof
/// (infeasible_pairs.h); the second robot of each pair proven unable to reach both targets is
/// drawn again (footprint kept), and the check repeats until no entangled pair is proven so.
/// "Not proven impossible" is not a proof of a plan, but it is what the planner checks.
#include <string>
#include <vector>

#include "fleet_planner/io/instance_generator.h"
#include "fleet_planner/runtime/deadline.h"

namespace fleet_planner {

struct FeasibleGeneration {
  Instance instance;
  int rounds = 0;                   ///< checks made (1: the first draw had no proven pair)
  std::vector<std::string> redrawn;  ///< "robot '7' (with '12'): <the proof's message>", in order
  bool clean = false;               ///< the last check proved no pair (false: rounds or time ran out)
};

/// generateInstance(map, options) with the check above, at most `max_rounds` checks; each pair
/// proof stops after `pair_expansions`. Deterministic when the deadline does not cut in. Throws
/// InvalidInput like generateInstance, and when a robot cannot be drawn again.
FeasibleGeneration generateFeasibleInstance(const GridMap& map, const GeneratorOptions& options, int max_rounds = 10,
                                            long long pair_expansions = 500'000, const Deadline& deadline = {});

}  // namespace fleet_planner
