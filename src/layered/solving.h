#pragma once
// The state of one solveSubproblems call (subproblem_solving.h), private to the layered planner.
// Its members are defined in four files, one concern each:
//   subproblem_solving.cpp    the loop: solve what is pending, prove, step aside, merge, repeat;
//   subproblem_scheduling.cpp units of work on the thread pool, and merging their plans;
//   subproblem_attempt.cpp    one subproblem: its obstacles, time share, backend and fallback;
//   safeguards.cpp            pair proofs, stepping aside, merging a failed subproblem.
#include <atomic>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "fleet_planner/layered/subproblem_solving.h"

namespace fleet_planner {

/// Names of the first robots of `robots` ("a,b,c,... (12 robots)"), for reasons and reports.
std::string idsOf(const Instance& instance, const std::vector<int>& robots);

class Solving {
 public:
  Solving(const Instance& instance, const FleetGraphs& graphs, const SubproblemSolvingOptions& options,
          const Deadline& deadline);
  SubproblemSolving run(std::vector<SolvedSubproblem> order);

 private:
  struct SolveAttempt {
    SolveResult result;
    bool delayed = false;  // planned with the earlier levels of its cluster at their targets
  };

  // Units of work: a subproblem (parallel backends) or the unsolved rest of a cluster's chain
  // (serial backends), in order. A chain behind a failed level waits until a merge resolves it.
  std::vector<std::vector<std::size_t>> pendingUnits() const;
  void solvePending();
  // The robots of the other subproblems where subproblem k sees them: earlier ones at their
  // targets, later ones at their starts.
  std::vector<StaticFootprint> standingFor(std::size_t k) const;
  void solveOne(std::size_t k);
  // `sub` solved by `backend`. Around many timed paths, a low-level search can take long to find
  // the gaps between them. Past a budget, the level is planned as a parallel backend would (the
  // earlier levels of its cluster at their targets) and delayed until it fits among them, which
  // always works.
  SolveAttempt solveByBackend(const std::string& backend, Subproblem sub);
  // `sub` with its moving obstacles turned into blocked targets, solved, and delayed until it
  // fits among their paths.
  SolveResult solveThenDelay(const std::string& backend, Subproblem sub,
                             const SolveStats& first_attempt);
  // Before solving: a pair of the decomposition's entangled pairs proven unable to reach both
  // targets.
  std::optional<std::string> entangledPairProof();
  // A pair of subproblem k's robots that no plan can serve, if one is proven among the pairs
  // not tried before. With the entangled pairs known, those among its robots (the others can
  // go one after the other). Else: first the pairs the failure named (a knot the backend proved
  // impossible around the other subproblems, the colliding pairs it was left with), then the
  // others.
  std::optional<std::string> infeasiblePairIn(std::size_t k);
  // The first of `pairs` not tried before proven unable to reach both targets; each pair is
  // tried once (one cut short by the deadline counts as tried).
  std::optional<std::string> proveAmong(const std::vector<std::pair<int, int>>& pairs,
                                        const Deadline& deadline);
  // Safeguard, before a merge: subproblem k solved again with the robots of other subproblems
  // near its robots' ways, or on the paths of a plan of its robots alone, free to step aside
  // (step_aside.h). For a serial backend it leaves its
  // cluster's chain: it and the rest of the chain become clusters of their own, so that it is
  // planned with the earlier levels at their targets and merged by delay. False if no robot
  // stands near.
  bool letStepAside(std::size_t k, const SolveResult& failed);
  std::vector<StaticFootprint> standingInTheWay(std::size_t k) const;
  // The standing robots on the paths of a plan of subproblem k's robots alone among the static
  // obstacles (LA-LNS within its share of the time; none if it finds no plan).
  std::vector<StaticFootprint> standingOnItsPlan(std::size_t k) const;
  // Safeguard: merge subproblem k with the next one (or, for the last, with the one before);
  // their clusters become one. Results that depended on either are dropped.
  void mergeWithNeighbour(std::size_t k, const SolveResult& failed);
  // Algorithm 5: each unit's paths, delayed at the starts until they fit among the earlier ones.
  std::vector<Path> mergePlans();

  int robotsOf(std::size_t k) const { return static_cast<int>(order_[k].robots.size()); }
  /// The reason of subproblem k's failure, for messages.
  std::string failureOf(std::size_t k, const SolveResult& failed) const {
    return results_[k] ? failed.reason : std::string("not solved");
  }

  const Instance& instance_;
  const FleetGraphs& graphs_;
  SubproblemSolvingOptions options_;
  Deadline deadline_;
  bool serial_;
  std::vector<SolvedSubproblem> order_;
  std::vector<std::optional<SolveResult>> results_;
  std::vector<std::string> merges_;
  std::vector<std::string> step_asides_;
  std::set<std::pair<int, int>> tried_pairs_;
  // Robots of the subproblems of this round (solvePending) not solved yet, or being solved.
  std::atomic<int> pending_robots_{0};
};

}  // namespace fleet_planner
