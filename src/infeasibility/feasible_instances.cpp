#include "fleet_planner/infeasibility/feasible_instances.h"

#include <algorithm>

#include "fleet_planner/decomposition/decomposition.h"
#include "fleet_planner/infeasibility/infeasible_pairs.h"
#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

std::vector<PairToRedraw> pairsToRedraw(const Instance& instance, const FleetGraphs& graphs,
                                        const std::vector<std::pair<int, int>>& pairs, long long pair_expansions,
                                        const Deadline& deadline, long long backward_configurations) {
  std::vector<PairToRedraw> out;
  std::vector<bool> taken(instance.robots.size(), false);
  for (const auto& [a, b] : pairs) {
    if (taken[a] || taken[b]) continue;
    // A pair not shown possible is drawn again as well as one proven impossible: the
    // instance is meant to have a plan, and an undecided pair may not.
    const PairDecision decision = decidePair(instance, graphs, a, b, pair_expansions, deadline, backward_configurations);
    if (decision.verdict == PairVerdict::Possible || deadline.expired()) continue;
    taken[b] = true;
    const std::string what = decision.verdict == PairVerdict::Impossible
                                 ? "cannot both reach their targets, even alone on the map"
                                 : "are not shown able to both reach their targets";
    out.push_back({b, a, "robots '" + instance.robots[a].id + "' and '" + instance.robots[b].id + "' " + what +
                             " (" + decision.why + ")"});
  }
  return out;
}

FeasibleGeneration generateFeasibleInstance(const GridMap& map, const GeneratorOptions& options, int max_rounds,
                                            long long pair_expansions, const Deadline& deadline) {
  FeasibleGeneration out;
  out.instance = generateInstance(map, options);
  std::vector<Footprint> footprints;
  for (Robot& r : out.instance.robots) {
    r.footprint.sweep_tolerance = options.check_sweep_tolerance;  // the check's model
    footprints.push_back(r.footprint);
  }
  const FleetGraphs graphs(map, footprints, options.model);
  Rng rng(options.seed ^ 0x9e3779b97f4a7c15ULL);  // redraws: a stream of their own
  const std::vector<bool> everyone(out.instance.robots.size(), true);
  while (out.rounds < max_rounds && !deadline.expired()) {
    ++out.rounds;
    const Decomposition d = decompose(out.instance, graphs, DecompositionOptions{}, deadline);
    std::vector<bool> redraw(out.instance.robots.size(), false);
    for (const PairToRedraw& p : pairsToRedraw(out.instance, graphs, d.entangled_pairs, pair_expansions, deadline)) {
      redraw[p.robot] = true;
      out.redrawn.push_back("robot '" + out.instance.robots[p.robot].id + "' (with '" +
                            out.instance.robots[p.other].id + "'): " + p.why);
    }
    if (std::none_of(redraw.begin(), redraw.end(), [](bool r) { return r; })) {
      out.clean = !deadline.expired();
      break;
    }
    for (std::size_t i = 0; i < redraw.size(); ++i) {
      if (!redraw[i]) continue;
      std::vector<bool> others = everyone;
      others[i] = false;
      if (!placeRobot(graphs, out.instance, static_cast<int>(i), others, rng, options.attempts_per_robot)) {
        throw InvalidInput("generator: could not draw robot '" + out.instance.robots[i].id + "' again on " +
                           (map.source().empty() ? std::string("the map") : map.source()));
      }
    }
  }
  for (Robot& r : out.instance.robots) r.footprint.sweep_tolerance = 0.0;  // as drawn
  return out;
}

}  // namespace fleet_planner
