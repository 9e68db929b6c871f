// LA-LNS; see la_lns.h for the reference.
#include "fleet_planner/solvers/lns/la_lns.h"

#include <algorithm>
#include <exception>
#include <numeric>
#include <thread>

#include "fleet_planner/solvers/lns/end_game.h"
#include "fleet_planner/solvers/lns/parking_orders.h"
#include "fleet_planner/solvers/lns/parking_plan.h"
#include "fleet_planner/solvers/lns/stage_clearing.h"
#include "fleet_planner/solvers/registry.h"
#include "fleet_planner/solvers/search/safe_interval_search.h"
#include "fleet_planner/solvers/search/soft_path_search.h"
#include "fleet_planner/solvers/search/solve_common.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "lns_search.h"

namespace fleet_planner {

namespace {

const bool kRegistered = registerSolver("la_lns", [] { return std::make_unique<LaLns>(); });

// Stalled repairs after which the neighbourhood grows (and, at every agent, the search may give
// up): fewer for a knot, whose every repair is already the joint repair of all of it.
int stallRepairs(const LaLnsOptions& o, int agents) {
  return agents <= o.joint_robots ? o.knot_stall_repairs : o.stall_repairs;
}

}  // namespace

LnsSearch::LnsSearch(const SearchSpace& space, const Subproblem& problem,
                     const LaLnsOptions& options, SolveStats& stats)
    : space_(space),
      problem_(&problem),
      options_(options),
      stats_(&stats),
      n_(space.numAgents()),
      table_(space),
      rng_(problem.seed),
      partners_(n_),
      ideal_(n_),
      ideal_absent_(n_, false),
      escalation_(n_, 1),
      splice_failed_at_(n_, -1),
      growth_(options.neighborhood_size, stallRepairs(options, n_), n_) {
  weights_.fill(1.0);
}

SolveResult LnsSearch::run() {
  if (!problem_->returning.empty()) {
    if (std::optional<SolveResult> cleared = clearedStage()) return *cleared;
  }
  std::vector<int> order(n_);
  std::iota(order.begin(), order.end(), 0);
  // Longest first: the agents with most to do get the freest space.
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) {
    return space_.distance(x, space_.start(x)) > space_.distance(y, space_.start(y));
  });
  std::vector<char> parked(n_, 0);
  if (options_.parking_expansions > 0 && n_ >= options_.parking_robots) {
    if (std::optional<SolveResult> done = parkFirst(order, parked)) return *done;
  }
  for (int a : order) {
    if (parked[a]) continue;
    StatePath path;
    // A robot the parking plan left has no collision-free path: it starts from its shortest
    // one, and the repairs take it from there (a soft search around the parking plan's long
    // paths costs much of the time the repairs need).
    if (parked_partly_) path = shortestAlone(a);
    if (path.empty()) {
      if (std::optional<SolveResult> stop = initialPath(a, path)) return *stop;
    }
    table_.insert(a, path);
    ++planned_;
  }
  for (int a = 0; a < n_; ++a) partners_[a] = table_.partners(a);
  if (options_.portfolio_robots > 0 && n_ >= options_.portfolio_robots && problem_->threads >= 2 &&
      collidingPairs() > 0) {
    return race();
  }
  return repairs(nullptr, 0);
}

SolveResult LnsSearch::repairs(LnsRace* race, int me) {
  long long made = 0;
  // An outcome after `made` repairs: recorded in a race.
  auto outcome = [&](SolveResult r) {
    if (race) race->outcome_at[me] = made;
    return r;
  };
  while (true) {
    if (race && race->beaten(me, made)) return SolveResult{};
    if (collidingPairs() == 0) {
      // The table's answer, checked by the backends' own conflict code before it is returned.
      std::vector<StatePath> paths(n_);
      for (int a = 0; a < n_; ++a) paths[a] = table_.path(a);
      const std::optional<AgentConflict> c = firstConflict(space_, paths);
      if (!c) return outcome(success(paths));
      link(c->a, c->b);
    }
    if (std::optional<SolveResult> stop = outOfBudget()) return *stop;
    // Only the first search asks the caller (and so gives up in a race).
    if (me == 0 && growth_.exhausted() > 0 && mayGiveUp()) {
      return outcome(timeout("stuck after " + std::to_string(stallRepairs(options_, n_)) +
                             " repairs of every robot without fewer colliding pairs"));
    }
    if (me == 0 && problem_->ends_when_stalled && growth_.sinceBest() >= options_.end_stall_repairs) {
      return outcome(timeout("no fewer colliding pairs in " + std::to_string(options_.end_stall_repairs) +
                             " repairs"));
    }
    if (race && race->beaten(me, made + 1)) return SolveResult{};
    repair();
    ++made;
    if (race) race->repairs[me] = made;
    if (proof_) {
      SolveResult r = failedResult(SolveStatus::Infeasible, *proof_);
      r.culprits = proof_culprits_;
      return outcome(r);
    }
  }
}

SolveResult LnsSearch::race() {
  LnsRace race;
  SolveStats other_stats;
  // The copy: the same first plan and state, another seed, its own statistics, and a deadline
  // that this thread calls off once the copy can no longer win.
  Subproblem other_problem = *problem_;
  other_problem.seed = problem_->seed ^ 0x9e3779b97f4a7c15ULL;
  other_problem.deadline =
      Deadline(problem_->deadline.end(), &race.call_off).withMemoryGuard(problem_->deadline.memoryGuard());
  // The caller is asked on this thread only (Subproblem::may_give_up is not made for two): the
  // answer, which pair proofs also read, is kept before the copy is made.
  mayGiveUp();
  LnsSearch other(*this);
  other.stats_ = &other_stats;
  other.rng_ = Rng(other_problem.seed);
  other.problem_ = &other_problem;
  SolveResult theirs;
  std::exception_ptr failure;  // search 1's, unless it was called off first
  std::thread helper([&] {
    try {
      theirs = other.repairs(&race, 1);
    } catch (...) {
      if (!race.call_off) failure = std::current_exception();
    }
  });
  SolveResult mine;
  try {
    mine = repairs(&race, 0);
  } catch (...) {
    race.call_off = true;
    helper.join();
    throw;
  }
  // Search 1 is called off unless it may still reach an outcome before this one's.
  const long long at = race.outcome_at[0].load();
  if (at == LnsRace::kNone || race.repairs[1].load() + 1 >= at) race.call_off = true;
  helper.join();
  if (failure) std::rethrow_exception(failure);
  stats_->low_level_expansions += other_stats.low_level_expansions;
  stats_->high_level_nodes += other_stats.high_level_nodes;
  const long long theirs_at = race.outcome_at[1].load();
  const bool they_win = theirs_at != LnsRace::kNone && (at == LnsRace::kNone || theirs_at < at);
  return they_win ? theirs : mine;
}

// A packed subproblem: first the robots that get home one at a time, pushing the others aside
// (parking_plan.h), each put in the table and marked in `parked`; the plan if all got home.
std::optional<SolveResult> LnsSearch::parkFirst(const std::vector<int>& order, std::vector<char>& parked) {
  ParkingPlanOptions o;
  o.max_pockets = std::max(1, options_.pockets);
  o.max_expansions = std::max(options_.parking_expansions, options_.parking_expansions_per_robot * n_);
  const Deadline deadline = problem_->deadline.within(problem_->deadline.remaining() * options_.parking_share);
  o.order_slack = options_.parking_order_slack;
  // The orders of parking_orders.h, one of them kept (fastestParkingPlan).
  const std::vector<std::vector<int>> orders =
      parkingOrders(space_, order, options_.parking_orders, options_.parking_precedence_expansions);
  const std::optional<ParkingPlan> plan =
      fastestParkingPlan(space_, orders, deadline, o, problem_->threads, stats_->low_level_expansions);
  if (!plan) return std::nullopt;
  if (plan->robots_home == n_) return success(plan->paths);
  if (options_.end_game) {
    const Deadline end_deadline =
        problem_->deadline.within(problem_->deadline.remaining() * options_.end_game_share);
    const std::optional<std::vector<StatePath>> finished =
        endGame(space_, *problem_, plan->paths, plan->home, options_, end_deadline, EndGameOptions{},
                stats_->low_level_expansions);
    if (finished) return success(*finished);
  }
  // A subproblem of fewer than twice `parking_robots` robots that the parking plan leaves
  // unfinished starts from the soft first plan of all its robots instead: the soft repairs
  // converge there, and robots that wait in pockets make long paths to repair around.
  if (n_ < 2 * options_.parking_robots) {
    parked_partly_ = false;
    return std::nullopt;
  }
  parked_partly_ = true;
  for (int a = 0; a < n_; ++a) {
    if (!plan->home[a]) continue;
    table_.insert(a, plan->paths[a]);
    parked[a] = 1;
    ++planned_;
  }
  return std::nullopt;
}

// Agent a's shortest path around the hard obstacles only (static footprints, other
// subproblems' timed paths), by safe intervals: a wait for another subproblem's robot to pass
// is one node, where space-time A* (idealPath) pays for it step by step. Cached as its ideal
// path; empty if none within the search's budget.
StatePath LnsSearch::shortestAlone(int a) {
  if (ideal_[a].empty() && !ideal_absent_[a]) {
    const SoftPathTable nobody(space_);
    const SafeIntervalResult r =
        safeIntervalSearch(space_, a, nobody, problem_->deadline, options_.max_expansions_per_search);
    stats_->low_level_expansions += r.expansions;
    if (r.outcome == SafeIntervalResult::Outcome::Found) ideal_[a] = r.path;
  }
  return ideal_[a];
}

// With returning robots (robots of other subproblems stepping aside): a plan of the others
// made without them, and the returning robots in its way clearing the stage for it
// (stage_clearing.h); none if either fails.
std::optional<SolveResult> LnsSearch::clearedStage() {
  std::vector<bool> returning(n_, false);
  Subproblem without;
  without.instance = problem_->instance;
  without.graphs = problem_->graphs;
  without.moving = problem_->moving;
  without.seed = problem_->seed;
  without.deadline = problem_->deadline.within(std::min(problem_->deadline.remaining() / 10, 2.0));
  std::vector<int> movers;
  for (int a = 0; a < n_; ++a) {
    const int r = space_.robot(a);
    returning[a] = std::any_of(problem_->returning.begin(), problem_->returning.end(),
                               [&](const StaticFootprint& f) { return f.robot == r; });
    if (!returning[a]) {
      movers.push_back(a);
      without.robots.push_back(r);
    }
  }
  if (movers.empty() || static_cast<int>(movers.size()) > options_.stage_robots) return std::nullopt;
  const SolveResult planned = LaLns(options_).solve(without);
  stats_->low_level_expansions += planned.stats.low_level_expansions;
  if (!planned.success()) return std::nullopt;
  std::vector<StatePath> alone(n_);
  std::vector<StatePath> moved = toStatePaths(space_, movers, planned.paths);
  for (std::size_t k = 0; k < movers.size(); ++k) alone[movers[k]] = std::move(moved[k]);
  const std::optional<std::vector<StatePath>> paths =
      clearTheStage(space_, returning, alone, problem_->deadline, options_.pockets,
                    options_.max_expansions_per_search, stats_->low_level_expansions);
  if (!paths) return std::nullopt;
  return success(*paths);
}

bool LnsSearch::mayGiveUp() {
  if (!may_give_up_) may_give_up_ = problem_->may_give_up && problem_->may_give_up();
  return *may_give_up_;
}

std::optional<SolveResult> LnsSearch::outOfBudget() const {
  if (problem_->deadline.cancelled()) return failedResult(SolveStatus::Cancelled, "cancelled");
  if (problem_->deadline.expired()) return timeout("time limit reached");
  if (problem_->max_expansions >= 0 && stats_->low_level_expansions > problem_->max_expansions)
    return timeout("expansion budget of " + std::to_string(problem_->max_expansions) + " used up");
  return std::nullopt;
}

SolveResult LnsSearch::timeout(const std::string& why) const {
  if (planned_ < n_) {
    return failedResult(SolveStatus::Timeout, why + " during the first plan (" +
                                                  std::to_string(planned_) + " of " +
                                                  std::to_string(n_) + " robots planned)");
  }
  SolveResult r = failedResult(SolveStatus::Timeout, why + " with " + std::to_string(collidingPairs()) +
                                                         " colliding pairs of robots left" + somePairs());
  for (int a = 0; a < n_; ++a) {
    for (int b : partners_[a]) {
      if (b > a) r.culprits.insert(r.culprits.end(), {space_.robot(a), space_.robot(b)});
    }
  }
  return r;
}

// " (a & b, c & d, ...)": the first few colliding pairs, to say where the plan is stuck.
std::string LnsSearch::somePairs() const {
  std::string out;
  int shown = 0;
  for (int a = 0; a < n_ && shown < 3; ++a) {
    for (int b : partners_[a]) {
      if (b <= a || shown == 3) continue;
      out += (shown++ == 0 ? " (" : ", ") + space_.label(a) + " & " + space_.label(b);
    }
  }
  if (shown == 0) return out;
  return out + (collidingPairs() > shown ? ", ...)" : ")");
}

// A path for a, around the agents planned so far as soft obstacles; if that search gives up,
// its shortest path in the static world and the other subproblems' timed paths.
std::optional<SolveResult> LnsSearch::initialPath(int a, StatePath& path) {
  SoftSearchResult r = search(a);
  if (r.outcome == SoftSearchResult::Outcome::Found) {
    path = std::move(r.path);
    return std::nullopt;
  }
  if (const std::optional<SolveResult> stop = outOfBudget()) return stop;
  const StatePath& ideal = idealPath(a);
  if (ideal.empty()) {
    if (const std::optional<SolveResult> stop = outOfBudget()) return stop;
    if (!ideal_absent_[a])
      return timeout(space_.label(a) + "'s first path search ran out of nodes");
    return failedResult(
        SolveStatus::Infeasible,
        space_.label(a) + " cannot reach its target around the other subproblems' robots");
  }
  path = ideal;
  return std::nullopt;
}

// An agent whose new path still collides gets a higher collision cost next time (doubling up
// to 64 times the base), so that a wait or a detour that a small cost would not pay for is
// found in the end; a collision-free path resets it.
SoftSearchResult LnsSearch::search(int a) {
  // A collision-free path first (safe intervals: long waits are cheap there), if there is one;
  // a robot whose target is passed late waits at its start where it can (safeIntervalHome).
  const SafeIntervalResult free = safeIntervalHome(space_, a, table_, space_.start(a), 0, problem_->deadline,
                                                   options_.max_expansions_per_search);
  stats_->low_level_expansions += free.expansions;
  if (free.outcome == SafeIntervalResult::Outcome::Found) {
    escalation_[a] = 1;
    SoftSearchResult r;
    r.outcome = SoftSearchResult::Outcome::Found;
    r.path = free.path;
    return r;
  }
  if (free.outcome == SafeIntervalResult::Outcome::Expired) {
    SoftSearchResult r;
    r.outcome = SoftSearchResult::Outcome::Expired;
    return r;
  }
  SoftSearchOptions o;
  o.collision_cost = options_.collision_cost * escalation_[a];
  o.max_expansions = options_.max_expansions_per_search;
  o.heuristic_weight = options_.heuristic_weight;
  SoftSearchResult r = softPathSearch(space_, a, table_, problem_->deadline, o);
  stats_->low_level_expansions += r.expansions;
  if (r.outcome == SoftSearchResult::Outcome::Found) {
    escalation_[a] = r.collisions == 0 ? 1 : std::min(escalation_[a] * 2, 64);
  } else if (r.outcome == SoftSearchResult::Outcome::NodeLimit) {
    escalation_[a] = std::max(escalation_[a] / 2, 1);
  }
  return r;
}

// Colliding pairs with at least one agent of `group`, given each agent's partners.
int LnsSearch::pairsTouching(const std::vector<int>& group,
                         const std::vector<std::vector<int>>& partners,
                         const std::vector<bool>& in) {
  int count = 0;
  for (int a : group) {
    for (int b : partners[a]) count += (!in[b] || a < b) ? 1 : 0;
  }
  return count;
}

SolveResult LnsSearch::success(const std::vector<StatePath>& paths) const {
  SolveResult r;
  r.status = SolveStatus::Success;
  r.paths = toPosePaths(space_, paths);
  return r;
}

SolveResult LaLns::solve(const Subproblem& problem) {
  (void)kRegistered;
  return solveWith(problem, /*moving_allowed=*/true,
                   [&](const SearchSpace& space, SolveStats& stats) {
                     LnsSearch search(space, problem, options_, stats);
                     return search.run();
                   });
}

}  // namespace fleet_planner
