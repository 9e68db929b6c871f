// Safeguards of a failed subproblem: pair proofs, stepping aside, merging with a neighbour; see
// subproblem_solving.h and solving.h.
#include <algorithm>

#include "fleet_planner/infeasibility/infeasible_pairs.h"
#include "fleet_planner/layered/step_aside.h"
#include "fleet_planner/solvers/registry.h"
#include "solving.h"

namespace fleet_planner {

// Before solving: a pair of the decomposition's entangled pairs proven unable to reach both
// targets.
std::optional<std::string> Solving::entangledPairProof() {
  if (!options_.entangled_known) return std::nullopt;
  return proveAmong(options_.entangled_pairs,
                    deadline_.within(deadline_.remaining() * options_.budget.pair_proof_share));
}

// A pair of subproblem k's robots that no plan can serve, if one is proven among the pairs
// not tried before. With the entangled pairs known, those among its robots (the others can
// go one after the other). Else: first the pairs the failure named (a knot the backend proved
// impossible around the other subproblems, the colliding pairs it was left with), then the
// others.
std::optional<std::string> Solving::infeasiblePairIn(std::size_t k) {
  const std::vector<int>& robots = order_[k].robots;
  auto in_k = [&](int r) { return std::find(robots.begin(), robots.end(), r) != robots.end(); };
  std::vector<std::pair<int, int>> pairs;
  auto add = [&](int a, int b) {
    if (a == b || pairs.size() >= options_.budget.pairs_per_failure) return;
    const std::pair<int, int> p{std::min(a, b), std::max(a, b)};
    if (!tried_pairs_.count(p) && std::find(pairs.begin(), pairs.end(), p) == pairs.end())
      pairs.push_back(p);
  };
  if (options_.entangled_known) {
    for (const auto& [a, b] : options_.entangled_pairs) {
      if (in_k(a) && in_k(b)) add(a, b);
    }
  } else {
    const std::vector<int> suspects = results_[k] ? results_[k]->culprits : std::vector<int>{};
    for (std::size_t i = 0; i + 1 < suspects.size(); i += 2) add(suspects[i], suspects[i + 1]);
    for (std::size_t j = 0; j < suspects.size(); ++j) {
      for (std::size_t i = 0; i < j; ++i) add(suspects[i], suspects[j]);
    }
    for (std::size_t i = 0; i < robots.size(); ++i) {
      for (std::size_t j = i + 1; j < robots.size(); ++j) add(robots[i], robots[j]);
    }
  }
  return proveAmong(pairs, deadline_.within(deadline_.remaining() * options_.budget.pair_proof_share));
}

// The first of `pairs` not tried before proven unable to reach both targets; each pair is
// tried once (one cut short by the deadline counts as tried).
std::optional<std::string> Solving::proveAmong(const std::vector<std::pair<int, int>>& pairs,
                                      const Deadline& deadline) {
  for (const auto& p : pairs) {
    if (deadline.expired()) break;
    if (!tried_pairs_.insert(p).second) continue;
    if (auto proof = findInfeasiblePair(instance_, graphs_, {p}, options_.budget.pair_proof_expansions, deadline))
      return proof;
  }
  return std::nullopt;
}

// The robots of other subproblems that may step aside for subproblem k.
std::vector<StaticFootprint> Solving::standingInTheWay(std::size_t k) const {
  const std::vector<int>& robots = order_[k].robots;
  return robotsInTheWay(instance_, graphs_, robots, standingFor(k), options_.budget.step_aside_margin,
                        std::max(options_.budget.step_aside_min_count, robots.size()));
}

// The standing robots on the paths of a plan of subproblem k's robots alone among the static
// obstacles (LA-LNS within its share of the time; none if it finds no plan or k is large).
std::vector<StaticFootprint> Solving::standingOnItsPlan(std::size_t k) const {
  if (order_[k].robots.size() > options_.budget.step_aside_plan_max_robots) return {};
  Subproblem sub;
  sub.instance = &instance_;
  sub.graphs = &graphs_;
  sub.robots = order_[k].robots;
  sub.seed = options_.seed + order_[k].seed_offset;
  sub.deadline = deadline_.within(std::min(deadline_.remaining() * options_.budget.step_aside_plan_share,
                                           options_.budget.step_aside_plan_max_s));
  const SolveResult alone = makeSolver("la_lns", options_.backend_parameters)->solve(sub);
  if (!alone.success()) return {};
  return robotsOnPaths(graphs_, sub.robots, alone.paths, standingFor(k));
}

// Safeguard, before a merge: subproblem k solved again with the robots of other subproblems
// near its robots' ways, or on the paths of a plan of its robots alone, free to step aside
// (step_aside.h). For a serial backend it leaves its
// cluster's chain: it and the rest of the chain become clusters of their own, so that it is
// planned with the earlier levels at their targets and merged by delay. False if no robot
// stands near.
bool Solving::letStepAside(std::size_t k, const SolveResult& failed) {
  SolvedSubproblem& s = order_[k];
  s.step_aside_tried = true;
  std::vector<StaticFootprint> near = standingInTheWay(k);
  for (const StaticFootprint& f : standingOnItsPlan(k)) {
    const bool known = std::any_of(near.begin(), near.end(), [&](const StaticFootprint& g) { return g.robot == f.robot; });
    if (!known) near.push_back(f);
  }
  if (near.empty()) return false;
  for (const StaticFootprint& f : near) s.stepping_aside.push_back(f.robot);
  step_asides_.push_back("subproblem " + std::to_string(k) + " (" + idsOf(instance_, s.robots) + ") failed: " +
                         (results_[k] ? failed.reason : std::string("not solved")) + "; solved again with " +
                         std::to_string(near.size()) + " robots of other subproblems free to step aside (" +
                         idsOf(instance_, s.stepping_aside) + ")");
  if (serial_) {
    int fresh = 0;
    for (const auto& o : order_) fresh = std::max(fresh, o.cluster + 1);
    const int chain = s.cluster;
    s.cluster = fresh;
    for (std::size_t m = k + 1; m < order_.size() && order_[m].cluster == chain; ++m) order_[m].cluster = fresh + 1;
  }
  results_[k].reset();
  return true;
}

// Safeguard: merge subproblem k with the next one (or, for the last, with the one before);
// their clusters become one. Results that depended on either are dropped.
void Solving::mergeWithNeighbour(std::size_t k, const SolveResult& failed) {
  const std::size_t other = k + 1 < order_.size() ? k + 1 : k - 1;
  const std::size_t first = std::min(k, other);
  merges_.push_back("subproblem " + std::to_string(k) + " (" + idsOf(instance_, order_[k].robots) + ") failed: " +
                    (results_[k] ? failed.reason : std::string("not solved")) + " (after " +
                    std::to_string(failed.stats.time_s).substr(0, 5) + " s, " +
                    std::to_string(failed.stats.high_level_nodes) + " high-level nodes, " +
                    std::to_string(failed.stats.low_level_expansions) + " expansions); merged with subproblem " +
                    std::to_string(other));
  const int keep = order_[first].cluster, gone = order_[first + 1].cluster;
  for (auto& s : order_) {
    if (s.cluster == gone) s.cluster = keep;
  }
  for (std::size_t m : {first, first + 1}) {
    order_[m].stepping_aside.clear();
    order_[m].step_aside_tried = false;
  }
  std::vector<int> joined = order_[first].robots;
  joined.insert(joined.end(), order_[first + 1].robots.begin(), order_[first + 1].robots.end());
  std::sort(joined.begin(), joined.end());
  order_[first].robots = joined;
  order_.erase(order_.begin() + static_cast<std::ptrdiff_t>(first) + 1);
  results_.erase(results_.begin() + static_cast<std::ptrdiff_t>(first) + 1);
  results_[first].reset();
  if (serial_) {
    for (std::size_t m = first + 1; m < order_.size() && order_[m].cluster == keep; ++m) results_[m].reset();
  }
}

}  // namespace fleet_planner
