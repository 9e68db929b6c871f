// Solving and merging the subproblems; see subproblem_solving.h.
#include "fleet_planner/layered/subproblem_solving.h"

#include <algorithm>
#include <atomic>
#include <optional>
#include <set>
#include <thread>

#include "fleet_planner/layered/infeasible_pairs.h"
#include "fleet_planner/layered/plan_merge.h"
#include "fleet_planner/layered/step_aside.h"
#include "fleet_planner/solvers/registry.h"

namespace fleet_planner {

namespace {

// Low-level expansions per robot a level may spend planning around the timed paths of its
// cluster's earlier levels before it is planned at their targets and delayed instead.
constexpr long long kChainExpansionsPerRobot = 50'000;

// Cells between a robot's shortest path and the footprint of a standing robot that may step
// aside for it; at most as many as the subproblem has robots (the nearest), and at least 8.
// Every failed subproblem gets this chance once, whatever its size: AR0044SR with 80 robots has a
// 21-robot level that LA-LNS brings to one colliding pair and no further in 50 s, and solves in
// 8 s once 21 standing robots may step aside.
constexpr int kStepAsideMargin = 2;
constexpr std::size_t kStepAsideMinCount = 8;

// Pairs of a failed subproblem's robots tried for an infeasibility proof (infeasible_pairs.h)
// per failure, the expansions of each, and the part of the time left they may take (before
// solving, for the entangled pairs; after each failure, for those of the failed subproblem).
constexpr std::size_t kPairsPerFailure = 120;
constexpr long long kPairExpansions = 500'000;
constexpr double kPairTimeShare = 0.1;

std::string idsOf(const Instance& instance, const std::vector<int>& robots) {
  std::string out;
  for (std::size_t k = 0; k < robots.size() && k < 6; ++k) out += (k ? "," : "") + instance.robots[robots[k]].id;
  if (robots.size() > 6) out += ",... (" + std::to_string(robots.size()) + " robots)";
  return out;
}

// A subproblem's statistics count every attempt at it.
void addEarlierAttempt(SolveStats& stats, const SolveStats& earlier) {
  stats.time_s += earlier.time_s;
  stats.low_level_expansions += earlier.low_level_expansions;
  stats.high_level_nodes += earlier.high_level_nodes;
}

class Solving {
 public:
  Solving(const Instance& instance, const FleetGraphs& graphs, const SubproblemSolvingOptions& options,
          const Deadline& deadline)
      : instance_(instance), graphs_(graphs), options_(options), deadline_(deadline),
        serial_(makeSolver(options.backend)->avoidsMovingObstacles()) {}

  SubproblemSolving run(std::vector<SolvedSubproblem> order) {
    SubproblemSolving out;
    order_ = std::move(order);
    results_.assign(order_.size(), std::nullopt);
    if (std::optional<std::string> proof = entangledPairProof()) {
      out.status = SolveStatus::Infeasible;
      out.reason = *proof + "; found before solving";
      out.order = order_;
      return out;
    }
    for (;;) {
      solvePending();
      std::size_t k = 0;
      while (k < order_.size() && results_[k] && results_[k]->success()) ++k;
      if (k == order_.size()) break;
      const SolveResult failed = results_[k] ? *results_[k] : SolveResult{};
      if (deadline_.expired() || order_.size() == 1) {
        out.status = deadline_.outOfMemory() ? SolveStatus::ResourceLimit
                     : deadline_.cancelled() ? SolveStatus::Cancelled
                     : deadline_.expired()   ? SolveStatus::Timeout
                                             : failed.status;
        out.reason = "subproblem " + std::to_string(k) + " (" + idsOf(instance_, order_[k].robots) + "): " +
                     (results_[k] ? failed.reason : std::string("not solved"));
        out.order = order_;
        out.merges = merges_;
        out.step_asides = step_asides_;
        return out;
      }
      if (std::optional<std::string> proof = infeasiblePairIn(k)) {
        out.status = SolveStatus::Infeasible;
        out.reason = *proof + "; found after subproblem " + std::to_string(k) + " (" + idsOf(instance_, order_[k].robots) +
                     ") failed: " + (results_[k] ? failed.reason : std::string("not solved"));
        out.order = order_;
        out.merges = merges_;
        out.step_asides = step_asides_;
        return out;
      }
      if (!order_[k].step_aside_tried && letStepAside(k, failed)) continue;
      mergeWithNeighbour(k, failed);
    }
    out.paths = mergePlans();
    out.order = order_;
    out.merges = merges_;
    out.step_asides = step_asides_;
    return out;
  }

 private:
  // Units of work: a subproblem (parallel backends) or the unsolved rest of a cluster's chain
  // (serial backends), in order. A chain behind a failed level waits until a merge resolves it.
  std::vector<std::vector<std::size_t>> pendingUnits() const {
    std::vector<std::vector<std::size_t>> units;
    std::vector<int> failed_clusters;
    for (std::size_t k = 0; k < order_.size(); ++k) {
      if (results_[k] && !results_[k]->success()) failed_clusters.push_back(order_[k].cluster);
      if (results_[k]) continue;
      if (serial_ && std::find(failed_clusters.begin(), failed_clusters.end(), order_[k].cluster) !=
                         failed_clusters.end()) {
        continue;
      }
      const bool chained = serial_ && !units.empty() && order_[units.back().back()].cluster == order_[k].cluster &&
                           units.back().back() + 1 == k;
      if (chained) {
        units.back().push_back(k);
      } else {
        units.push_back({k});
      }
    }
    return units;
  }

  int robotsOf(std::size_t k) const { return static_cast<int>(order_[k].robots.size()); }

  void solvePending() {
    const auto units = pendingUnits();
    if (units.empty()) return;
    int pending = 0;
    for (const auto& u : units) {
      for (std::size_t k : u) pending += robotsOf(k);
    }
    pending_robots_ = pending;
    std::atomic<std::size_t> next{0};
    auto work = [&] {
      for (std::size_t u = next++; u < units.size(); u = next++) {
        for (std::size_t i = 0; i < units[u].size(); ++i) {
          const std::size_t k = units[u][i];
          solveOne(k);
          pending_robots_ -= robotsOf(k);
          if (results_[k]->success()) continue;
          // The rest of the chain plans around it: not in this round.
          for (std::size_t j = i + 1; j < units[u].size(); ++j)
            pending_robots_ -= robotsOf(units[u][j]);
          break;
        }
      }
    };
    const int threads = std::max(1, std::min<int>(options_.threads, static_cast<int>(units.size())));
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (auto& t : pool) t.join();
  }

  // The robots of the other subproblems where subproblem k sees them: earlier ones at their
  // targets, later ones at their starts.
  std::vector<StaticFootprint> standingFor(std::size_t k) const {
    std::vector<StaticFootprint> out;
    for (std::size_t m = 0; m < order_.size(); ++m) {
      if (m == k) continue;
      for (int r : order_[m].robots) out.push_back({r, m < k ? instance_.robots[r].target : instance_.robots[r].start});
    }
    return out;
  }

  void solveOne(std::size_t k) {
    Subproblem sub;
    sub.instance = &instance_;
    sub.graphs = &graphs_;
    sub.robots = order_[k].robots;
    sub.seed = options_.seed + order_[k].seed_offset;
    const std::vector<int>& aside = order_[k].stepping_aside;
    sub.robots.insert(sub.robots.end(), aside.begin(), aside.end());
    for (std::size_t m = 0; m < order_.size(); ++m) {
      if (m == k) continue;
      // A serial backend plans around its own cluster's earlier levels as they move.
      const bool own_chain = serial_ && m < k && order_[m].cluster == order_[k].cluster;
      for (std::size_t a = 0; a < order_[m].robots.size(); ++a) {
        const int r = order_[m].robots[a];
        const GridPose& pose = m < k ? instance_.robots[r].target : instance_.robots[r].start;
        if (own_chain) {
          sub.moving.push_back({r, results_[m]->paths[a]});
        } else if (std::find(aside.begin(), aside.end(), r) != aside.end()) {
          sub.returning.push_back({r, pose});
        } else {
          sub.blocked.push_back({r, pose});
        }
      }
    }
    // A time share: at least a quarter of what is left, more for a larger part of the robots
    // still to be solved in this round (those of subproblems solved or being solved included);
    // the last subproblem gets all of it. A share that runs out triggers the safeguard.
    const double share = k + 1 == order_.size()
                             ? 1.0
                             : std::max(0.25, static_cast<double>(sub.robots.size()) /
                                                  std::max(1, pending_robots_.load()));
    const Deadline share_deadline = deadline_.within(deadline_.remaining() * share);
    const bool has_fallback = !options_.fallback.empty() && options_.fallback != options_.backend;
    const double first_part = has_fallback ? 1.0 - options_.fallback_share : 1.0;
    sub.deadline = share_deadline.within(share_deadline.remaining() * first_part);
    SolveAttempt first = solveByBackend(options_.backend, sub);
    SolveResult solved = std::move(first.result);
    bool delayed = first.delayed;
    // The fallback backend, in the rest of the share, for what the backend failed to solve, by
    // the same protocol.
    bool by_fallback = false;
    if (has_fallback && !solved.success() && solved.status != SolveStatus::Infeasible &&
        !share_deadline.expired()) {
      Subproblem again = sub;
      again.deadline = share_deadline;
      SolveAttempt second = solveByBackend(options_.fallback, again);
      addEarlierAttempt(second.result.stats, solved.stats);
      if (!second.result.success()) {
        second.result.reason = options_.backend + ": " + solved.reason + "; " + options_.fallback +
                               ": " + second.result.reason;
      }
      by_fallback = second.result.success();
      delayed = second.delayed;
      solved = std::move(second.result);
    }
    SolvedSubproblem& s = order_[k];
    s.delayed_in_cluster = delayed;
    s.by_fallback = by_fallback;
    s.status = solved.status;
    s.reason = solved.reason;
    s.time_s = solved.stats.time_s;
    s.stats = solved.stats;
    ++s.attempts;
    results_[k] = std::move(solved);
  }

  struct SolveAttempt {
    SolveResult result;
    bool delayed = false;  // planned with the earlier levels of its cluster at their targets
  };

  // `sub` solved by `backend`. Around many timed paths, a low-level search can take long to find
  // the gaps between them. Past a budget, the level is planned as a parallel backend would (the
  // earlier levels of its cluster at their targets) and delayed until it fits among them, which
  // always works.
  SolveAttempt solveByBackend(const std::string& backend, Subproblem sub) {
    const bool around_paths = !sub.moving.empty();
    sub.max_expansions =
        around_paths ? kChainExpansionsPerRobot * static_cast<long long>(sub.robots.size()) : -1;
    SolveAttempt attempt;
    attempt.result = makeSolver(backend)->solve(sub);
    if (around_paths && !attempt.result.success() && !sub.deadline.expired()) {
      attempt.result = solveThenDelay(backend, sub, attempt.result.stats);
      attempt.delayed = true;
    }
    return attempt;
  }

  // `sub` with its moving obstacles turned into blocked targets, solved, and delayed until it
  // fits among their paths.
  SolveResult solveThenDelay(const std::string& backend, Subproblem sub,
                             const SolveStats& first_attempt) {
    const int n = static_cast<int>(instance_.robots.size());
    std::vector<Path> earlier(n);
    std::vector<char> done(n, 0);
    for (MovingObstacle& m : sub.moving) {
      sub.blocked.push_back({m.robot, instance_.robots[m.robot].target});
      earlier[m.robot] = std::move(m.path);
      done[m.robot] = 1;
    }
    sub.moving.clear();
    sub.max_expansions = -1;
    SolveResult solved = makeSolver(backend)->solve(sub);
    addEarlierAttempt(solved.stats, first_attempt);
    if (solved.success()) delayToFit(graphs_, earlier, done, sub.robots, solved.paths);
    return solved;
  }

  // Before solving: a pair of the decomposition's entangled pairs proven unable to reach both
  // targets.
  std::optional<std::string> entangledPairProof() {
    if (!options_.entangled_known) return std::nullopt;
    return proveAmong(options_.entangled_pairs,
                      deadline_.within(deadline_.remaining() * kPairTimeShare));
  }

  // A pair of subproblem k's robots that no plan can serve, if one is proven among the pairs
  // not tried before. With the entangled pairs known, those among its robots (the others can
  // go one after the other). Else: first the pairs the failure named (a knot the backend proved
  // impossible around the other subproblems, the colliding pairs it was left with), then the
  // others.
  std::optional<std::string> infeasiblePairIn(std::size_t k) {
    const std::vector<int>& robots = order_[k].robots;
    auto in_k = [&](int r) { return std::find(robots.begin(), robots.end(), r) != robots.end(); };
    std::vector<std::pair<int, int>> pairs;
    auto add = [&](int a, int b) {
      if (a == b || pairs.size() >= kPairsPerFailure) return;
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
    return proveAmong(pairs, deadline_.within(deadline_.remaining() * kPairTimeShare));
  }

  // The first of `pairs` not tried before proven unable to reach both targets; each pair is
  // tried once (one cut short by the deadline counts as tried).
  std::optional<std::string> proveAmong(const std::vector<std::pair<int, int>>& pairs,
                                        const Deadline& deadline) {
    for (const auto& p : pairs) {
      if (deadline.expired()) break;
      if (!tried_pairs_.insert(p).second) continue;
      if (auto proof = findInfeasiblePair(instance_, graphs_, {p}, kPairExpansions, deadline))
        return proof;
    }
    return std::nullopt;
  }

  // Safeguard, before a merge: subproblem k solved again with the robots of other subproblems
  // near its robots' ways free to step aside (step_aside.h). For a serial backend it leaves its
  // cluster's chain: it and the rest of the chain become clusters of their own, so that it is
  // planned with the earlier levels at their targets and merged by delay. False if no robot
  // stands near.
  bool letStepAside(std::size_t k, const SolveResult& failed) {
    SolvedSubproblem& s = order_[k];
    s.step_aside_tried = true;
    const std::vector<StaticFootprint> near =
        robotsInTheWay(instance_, graphs_, s.robots, standingFor(k), kStepAsideMargin,
                       std::max(kStepAsideMinCount, s.robots.size()));
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
  void mergeWithNeighbour(std::size_t k, const SolveResult& failed) {
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

  // Algorithm 5: each unit's paths, delayed at the starts until they fit among the earlier ones.
  std::vector<Path> mergePlans() {
    const int n = static_cast<int>(instance_.robots.size());
    std::vector<Path> paths(n);
    std::vector<char> done(n, 0);
    for (std::size_t k = 0; k < order_.size();) {
      std::size_t end = k + 1;
      if (serial_) {
        while (end < order_.size() && order_[end].cluster == order_[k].cluster) ++end;
      }
      std::vector<int> robots;
      std::vector<Path> fresh;
      for (std::size_t m = k; m < end; ++m) {
        robots.insert(robots.end(), order_[m].robots.begin(), order_[m].robots.end());
        robots.insert(robots.end(), order_[m].stepping_aside.begin(), order_[m].stepping_aside.end());
        fresh.insert(fresh.end(), results_[m]->paths.begin(), results_[m]->paths.end());
      }
      const int delay = delayToFit(graphs_, paths, done, robots, fresh);
      for (std::size_t a = 0; a < robots.size(); ++a) {
        appendDelayed(paths, robots[a], std::move(fresh[a]));
        done[robots[a]] = 1;
      }
      for (std::size_t m = k; m < end; ++m) order_[m].delay = delay;
      k = end;
    }
    return paths;
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

}  // namespace

SubproblemSolving solveSubproblems(const Instance& instance, const FleetGraphs& graphs,
                                   std::vector<SolvedSubproblem> order, const SubproblemSolvingOptions& options,
                                   const Deadline& deadline) {
  return Solving(instance, graphs, options, deadline).run(std::move(order));
}

}  // namespace fleet_planner
