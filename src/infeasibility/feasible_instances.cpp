#include "fleet_planner/infeasibility/feasible_instances.h"

#include <algorithm>

#include "fleet_planner/decomposition/decomposition.h"
#include "fleet_planner/infeasibility/infeasible_pairs.h"
#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

FeasibleGeneration generateFeasibleInstance(const GridMap& map, const GeneratorOptions& options, int max_rounds,
                                            long long pair_expansions, const Deadline& deadline) {
  FeasibleGeneration out;
  out.instance = generateInstance(map, options);
  std::vector<Footprint> footprints;
  for (const Robot& r : out.instance.robots) footprints.push_back(r.footprint);
  const FleetGraphs graphs(map, footprints, options.model);
  Rng rng(options.seed ^ 0x9e3779b97f4a7c15ULL);  // redraws: a stream of their own
  const std::vector<bool> everyone(out.instance.robots.size(), true);
  while (out.rounds < max_rounds && !deadline.expired()) {
    ++out.rounds;
    const Decomposition d = decompose(out.instance, graphs, DecompositionOptions{}, deadline);
    std::vector<bool> redraw(out.instance.robots.size(), false);
    for (const auto& [a, b] : d.entangled_pairs) {
      if (redraw[a] || redraw[b]) continue;
      if (auto proof = findInfeasiblePair(out.instance, graphs, {{a, b}}, pair_expansions, deadline)) {
        redraw[b] = true;
        out.redrawn.push_back("robot '" + out.instance.robots[b].id + "' (with '" + out.instance.robots[a].id +
                              "'): " + *proof);
      }
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
  return out;
}

}  // namespace fleet_planner
