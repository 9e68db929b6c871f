// One subproblem solved: its obstacles, its time share, the backend and the fallback; see
// solving.h.
#include <algorithm>

#include "fleet_planner/layered/plan_merge.h"
#include "fleet_planner/model/plan.h"
#include "fleet_planner/solvers/registry.h"
#include "solving.h"

namespace fleet_planner {

namespace {

// A subproblem's statistics count every attempt at it; a lower bound proven by any holds.
void addEarlierAttempt(SolveStats& stats, const SolveStats& earlier) {
  stats.time_s += earlier.time_s;
  stats.low_level_expansions += earlier.low_level_expansions;
  stats.high_level_nodes += earlier.high_level_nodes;
  stats.lower_bound = std::max(stats.lower_bound, earlier.lower_bound);
}

// The sum of the paths' costs (each to its last arrival at its final pose).
long long costOf(const SolveResult& r) {
  long long cost = 0;
  for (const Path& p : r.paths) cost += p.empty() ? 0 : pathCost(p, p.back());
  return cost;
}

}  // namespace

// The robots of the other subproblems where subproblem k sees them: earlier ones at their
// targets, later ones at their starts.
std::vector<StaticFootprint> Solving::standingFor(std::size_t k) const {
  std::vector<StaticFootprint> out;
  for (std::size_t m = 0; m < order_.size(); ++m) {
    if (m == k) continue;
    for (int r : order_[m].robots) out.push_back({r, m < k ? instance_.robots[r].target : instance_.robots[r].start});
  }
  return out;
}

void Solving::solveOne(std::size_t k) {
  Subproblem sub;
  sub.instance = &instance_;
  sub.graphs = &graphs_;
  sub.robots = order_[k].robots;
  sub.seed = options_.seed + order_[k].seed_offset;
  // Alone (the whole fleet as one subproblem), it has every thread to itself, and it may end
  // when it stalls if the caller has another way to plan the fleet.
  if (order_.size() == 1) {
    sub.threads = std::max(1, options_.threads);
    sub.ends_when_stalled = options_.whole_fleet_ends_when_stalled;
  }
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
  // A first attempt that robots of other subproblems may help by stepping aside ends when its
  // search is stuck rather than at the end of its share: the step aside gets the time.
  if (!order_[k].step_aside_tried && order_.size() > 1 && sub.robots.size() > 1)
    sub.may_give_up = [this, k] { return !standingInTheWay(k).empty(); };
  // A time share: at least half of what is left, more for a larger part of the robots
  // still to be solved in this round (those of subproblems solved or being solved included);
  // the last subproblem gets all of it. A share that runs out triggers the safeguard.
  const double share = k + 1 == order_.size()
                           ? 1.0
                           : std::max(options_.budget.min_subproblem_share, static_cast<double>(sub.robots.size()) /
                                                std::max(1, pending_robots_.load()));
  const Deadline share_deadline = deadline_.within(deadline_.remaining() * share);
  const bool has_fallback = !options_.fallback.empty() && options_.fallback != options_.backend;
  const double first_part = has_fallback ? 1.0 - options_.budget.fallback_share : 1.0;
  sub.deadline = share_deadline.within(share_deadline.remaining() * first_part);
  SolveAttempt first = solveByBackend(options_.backend, sub);
  SolveResult solved = std::move(first.result);
  bool delayed = first.delayed;
  // The fallback backend, in the rest of the share, for what the backend failed to solve, by
  // the same protocol; and for a plan the backend had in hand when its limit stopped it, whose
  // cost proves nothing: the cheaper of the two plans is kept.
  bool by_fallback = false;
  if (has_fallback && (!solved.success() || solved.stopped_early) && solved.status != SolveStatus::Infeasible &&
      !share_deadline.expired()) {
    Subproblem again = sub;
    again.deadline = share_deadline;
    SolveAttempt second = solveByBackend(options_.fallback, again);
    addEarlierAttempt(second.result.stats, solved.stats);
    const bool keep_first = solved.success() && (!second.result.success() || costOf(solved) <= costOf(second.result));
    if (keep_first) {
      solved.stats = second.result.stats;
    } else {
      if (!second.result.success()) {
        second.result.reason = options_.backend + ": " + solved.reason + "; " + options_.fallback +
                               ": " + second.result.reason;
      }
      by_fallback = second.result.success();
      delayed = second.delayed;
      solved = std::move(second.result);
    }
  }
  SolvedSubproblem& s = order_[k];
  s.delayed_in_cluster = delayed;
  s.by_fallback = by_fallback;
  s.stopped_early = solved.success() && solved.stopped_early;
  s.status = solved.status;
  s.reason = solved.reason;
  s.time_s = solved.stats.time_s;
  s.stats = solved.stats;
  ++s.attempts;
  results_[k] = std::move(solved);
}

// `sub` solved by `backend`. Around many timed paths, a low-level search can take long to find
// the gaps between them. Past a budget, the level is planned as a parallel backend would (the
// earlier levels of its cluster at their targets) and delayed until it fits among them, which
// always works.
Solving::SolveAttempt Solving::solveByBackend(const std::string& backend, Subproblem sub) {
  const bool around_paths = !sub.moving.empty();
  sub.max_expansions =
      around_paths ? options_.budget.chain_expansions_per_robot * static_cast<long long>(sub.robots.size()) : -1;
  SolveAttempt attempt;
  attempt.result = makeSolver(backend, options_.backend_parameters)->solve(sub);
  if (around_paths && !attempt.result.success() && !sub.deadline.expired()) {
    attempt.result = solveThenDelay(backend, sub, attempt.result.stats);
    attempt.delayed = true;
  }
  return attempt;
}

// `sub` with its moving obstacles turned into blocked targets, solved, and delayed until it
// fits among their paths.
SolveResult Solving::solveThenDelay(const std::string& backend, Subproblem sub,
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
  SolveResult solved = makeSolver(backend, options_.backend_parameters)->solve(sub);
  addEarlierAttempt(solved.stats, first_attempt);
  if (solved.success()) delayToFit(graphs_, earlier, done, sub.robots, solved.paths);
  return solved;
}

}  // namespace fleet_planner
