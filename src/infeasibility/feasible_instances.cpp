#include "fleet_planner/infeasibility/feasible_instances.h"

#include <algorithm>

#include "fleet_planner/decomposition/decomposition.h"
#include "fleet_planner/infeasibility/infeasible_pairs.h"
#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

std::vector<PairToRedraw> pairsToRedraw(const Instance& instance, const FleetGraphs& graphs,
                                        const std::vector<std::pair<int, int>>& pairs, long long pair_expansions,
                                        const Deadline& deadline, long long backward_configurations) {
  // The pairs not shown possible: proven impossible, or undecided (the instance is meant to
  // have a plan, and an undecided pair may not).
  struct Bad {
    int a, b;
    std::string why;
  };
  std::vector<Bad> bad;
  for (const auto& [a, b] : pairs) {
    const PairDecision decision = decidePair(instance, graphs, a, b, pair_expansions, deadline, backward_configurations);
    if (deadline.expired()) break;
    if (decision.verdict == PairVerdict::Possible) continue;
    const std::string what = decision.verdict == PairVerdict::Impossible
                                 ? "cannot both reach their targets, even alone on the map"
                                 : "are not shown able to both reach their targets";
    bad.push_back({a, b, "robots '" + instance.robots[a].id + "' and '" + instance.robots[b].id + "' " + what +
                             " (" + decision.why + ")"});
  }
  // The robots drawn again cover those pairs: the robot in most pairs left first (a robot whose
  // start or target blocks several others is drawn again, not each of them), ties to the
  // higher index (the second of a pair).
  std::vector<PairToRedraw> out;
  std::vector<bool> covered(bad.size(), false);
  for (;;) {
    std::vector<int> count(instance.robots.size(), 0);
    for (std::size_t k = 0; k < bad.size(); ++k) {
      if (covered[k]) continue;
      ++count[bad[k].a];
      ++count[bad[k].b];
    }
    int robot = -1;
    for (int r = 0; r < static_cast<int>(count.size()); ++r) {
      if (count[r] > 0 && (robot < 0 || count[r] >= count[robot])) robot = r;
    }
    if (robot < 0) break;
    bool named = false;
    for (std::size_t k = 0; k < bad.size(); ++k) {
      if (covered[k] || (bad[k].a != robot && bad[k].b != robot)) continue;
      covered[k] = true;
      if (named) continue;
      out.push_back({robot, bad[k].a == robot ? bad[k].b : bad[k].a, bad[k].why});
      named = true;
    }
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
