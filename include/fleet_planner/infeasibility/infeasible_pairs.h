#pragma once
/// Proof that an instance has no plan (beyond the paper): two of its robots that cannot both
/// reach their targets even alone on the map. Dropping robots from a valid plan leaves a valid
/// plan, so such a pair makes the whole instance infeasible. LA-LaCAM decides a pair: its search
/// over joint configurations is complete, and it ends either with a plan or with every reachable
/// configuration explored. Where it runs out of expansions first (an open map has many
/// configurations to explore), the search backwards from the pair's goal (pair_goal_search.h)
/// may still decide it. Most pairs tried are not impossible: a plan of one robot after the
/// other, found first, shows that in a few single-robot searches (LA-LaCAM may take seconds
/// to find the manoeuvre on a real map). Used on the decomposition's entangled pairs and on
/// subproblems that failed, where a knot of robots that no backend unties may be no knot but an
/// impossibility (e.g. a wide robot whose start and target fill the only corridor that another
/// robot must cross).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

/// Robots a and b (instance indices of `around.instance`) searched by LA-LaCAM alone, among
/// `around`'s static footprints (blocked and returning) and nothing else: no other robot, no
/// moving obstacle. INFEASIBLE proves that they cannot both reach their targets among those
/// obstacles, and so that no problem containing them (with those obstacles or fewer) has a plan;
/// SUCCESS that they can; anything else decides nothing. The search stops after
/// `max_expansions` or at the deadline.
SolveResult searchPairAlone(const Subproblem& around, int a, int b, long long max_expansions, const Deadline& deadline);

/// Robots a and b alone among `around`'s static footprints, planned one after the other: the
/// first on its own, the second around the first's path (and the first standing at its target
/// for good), in the order a, b and then b, a. SUCCESS with the plan if an order serves, else
/// TIMEOUT (which decides nothing: the pair may need both to manoeuvre). Each single-robot
/// search stops after `max_expansions_per_search` or at the deadline.
SolveResult planPairInTurn(const Subproblem& around, int a, int b, long long max_expansions_per_search,
                           const Deadline& deadline);

/// What the pair proof says of two robots alone on the map (the map's obstacles only).
enum class PairVerdict {
  Possible,    ///< a plan of the pair was found (planned in turn, forwards or backwards)
  Impossible,  ///< every configuration explored (forwards or backwards): no plan
  Undecided,   ///< the budget or the deadline ran out first
};
struct PairDecision {
  PairVerdict verdict = PairVerdict::Undecided;
  std::string why;  ///< for Impossible, the proof; for Undecided, what ran out
};

/// Joint configurations the backward search of a pair's goal may collect (about 40 bytes each).
constexpr long long kPairBackwardConfigurations = 1'000'000;

/// Robots a and b (instance indices) alone on the map: planned in turn first (cheap, and most
/// pairs are possible), then searched backwards from their targets a little, forwards by
/// LA-LaCAM for at most `max_expansions`, and backwards again for at most
/// `backward_configurations` configurations.
PairDecision decidePair(const Instance& instance, const FleetGraphs& graphs, int a, int b, long long max_expansions,
                        const Deadline& deadline,
                        long long backward_configurations = kPairBackwardConfigurations);

/// The first of `pairs` (instance indices) proven unable to reach both targets, as a message
/// naming both robots; nullopt if none is proven (a pair planned in turn is not searched
/// further; each pair's forward search stops after
/// `max_expansions`, its backward search after a million configurations, and all stop at the
/// deadline).
std::optional<std::string> findInfeasiblePair(const Instance& instance, const FleetGraphs& graphs,
                                              const std::vector<std::pair<int, int>>& pairs,
                                              long long max_expansions, const Deadline& deadline);

}  // namespace fleet_planner
