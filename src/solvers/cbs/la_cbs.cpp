// LA-CBS; see la_cbs.h for the references.
#include "fleet_planner/solvers/cbs/la_cbs.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <set>

#include "fleet_planner/solvers/search/agent_conflicts.h"
#include "fleet_planner/solvers/cbs/cbs_split.h"
#include "fleet_planner/solvers/cbs/pairwise_delay.h"
#include "fleet_planner/solvers/cbs/path_around_others.h"
#include "fleet_planner/solvers/registry.h"
#include "fleet_planner/solvers/search/solve_common.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "tree_frontier.h"

namespace fleet_planner {

namespace {

const bool kRegistered = registerSolver("la_cbs", [] { return std::make_unique<LaCbs>(); });

// A constraint-tree node stores only what it changes: its constraints and the paths it replanned.
struct CtNode {
  int parent = -1;
  std::vector<CbsConstraint> constraints;
  std::vector<std::pair<int, StatePath>> paths;
  std::vector<int> path_bounds;  // per entry of `paths`: a lower bound on that agent's cost
  long long cost = 0;
  long long bound_sum = 0;  // the agents' lower bounds (their costs unless the search is focal)
  // A lower bound on any plan below: bound_sum + the pairwise delay heuristic.
  long long f = 0;
  int conflicts = 0;
  int pairs = 0;  // agent pairs with a conflict
  void count(const ConflictTally& t) { conflicts = t.conflicts; pairs = static_cast<int>(t.pairs.size()); }
};

// A split evaluated before choosing: its children (one per feasible branch) and how many of its
// branches raise the cost (2: cardinal, 1: semi-cardinal, 0: non-cardinal; an infeasible branch
// counts as raising it).
struct EvaluatedSplit {
  std::vector<CtNode> children;
  int raising = 0;
};

class CbsSearch {
 public:
  /// The search over all agents of `space`, with the pairwise delay heuristic if enabled.
  CbsSearch(const SearchSpace& space, const Subproblem& problem, const LaCbsOptions& options)
      : space_(space), problem_(problem), options_(options), n_(space.numAgents()) {
    for (int a = 0; a < n_; ++a) active_.push_back(a);
    if (options_.max_high_level_nodes >= 0 || options_.max_total_expansions >= 0) {
      max_nodes_ = options_.max_high_level_nodes >= 0 ? options_.max_high_level_nodes
                                                      : std::numeric_limits<long long>::max();
      max_expansions_ = options_.max_total_expansions >= 0 ? options_.max_total_expansions
                                                           : std::numeric_limits<long long>::max();
    }
    if (options_.pairwise_delay_nodes > 0 && n_ > 2) pairs_.emplace(n_);  // a pair's bound is its search
  }
  /// The search over agents i and j only (the others have empty paths), without heuristic,
  /// that stops after `max_nodes` expansions or once its low-level searches have expanded
  /// `max_expansions` states: it bounds the pair's cost from below.
  CbsSearch(const SearchSpace& space, const Subproblem& problem, const LaCbsOptions& options, int i, int j,
            long long max_nodes, long long max_expansions)
      : space_(space), problem_(problem), options_(options), n_(space.numAgents()), active_{i, j},
        max_nodes_(max_nodes), max_expansions_(max_expansions) {}

  SolveResult run() {
    SolveResult r = search();
    stats_.lower_bound = lower_bound_;
    // Anytime: stopped by a limit with a conflict-free plan in hand, that plan is the answer; the
    // tree's lower bound (in the statistics) says how far from the optimum it can be.
    if (r.status == SolveStatus::Timeout && options_.anytime && incumbent_) {
      r = success(*incumbent_);
      r.stopped_early = true;
      r.reason = "stopped before proving the optimum: the cheapest plan found costs " +
                 std::to_string(incumbent_cost_) + ", any plan at least " + std::to_string(lower_bound_);
    }
    return r;
  }

  SolveResult search() {
    CtNode root;
    std::vector<StatePath> paths(n_);
    std::vector<int> bounds(n_, 0);
    for (const int a : active_) {
      const AgentConstraints none;
      LowLevelResult ll = lowLevel(a, none, paths);
      if (ll.outcome != LowLevelResult::Outcome::Found) return lowLevelFailure(a, ll, true);
      paths[a] = std::move(ll.path);
      bounds[a] = ll.lower_bound;
    }
    for (const int a : active_) {
      root.cost += pathCost(paths[a]);
      root.bound_sum += bounds[a];
      root.paths.emplace_back(a, paths[a]);
      root.path_bounds.push_back(bounds[a]);
    }
    const ConflictTally tally = tallyConflicts(space_, paths);
    root.count(tally);
    if (!boundNode(root, tally.pairs, bounds)) return stopped();
    push(std::move(root));

    for (;;) {
      if (problem_.deadline.expired()) return stopped();
      const int id = open_.pop();
      if (id < 0) break;
      lower_bound_ = std::max(lower_bound_, open_.leastF());
      if (incumbentGoodEnough()) return success(*incumbent_);
      if (max_nodes_ >= 0 &&
          (stats_.high_level_nodes >= max_nodes_ || stats_.low_level_expansions >= max_expansions_)) {
        return failure(SolveStatus::Timeout, "constraint tree reached its node limit");
      }
      ++stats_.high_level_nodes;
      std::vector<int> bounds;
      std::vector<StatePath> current = pathsOf(id, bounds);
      std::optional<EvaluatedSplit> chosen;
      while (!chosen) {  // bypass may adopt paths and look again at the same node
        const std::vector<AgentConflict> earliest =
            earliestConflictPerPair(space_, current, std::max(1, options_.max_candidate_conflicts));
        if (earliest.empty()) {
          if (!focal()) lower_bound_ = nodes_[id].cost;
          return success(current);
        }
        tryAroundOthers(current, nodes_[id].pairs);
        if (incumbentGoodEnough()) return success(*incumbent_);
        if (problem_.deadline.expired()) return stopped();
        const AgentConflict& first = earliest.front();
        if (first.t == 0 && first.kind == AgentConflict::Kind::Vertex) {
          return failure(SolveStatus::Infeasible,
                         space_.label(first.a) + " and " + space_.label(first.b) + " overlap at their starts");
        }
        std::vector<AgentConflict> candidates;
        if (options_.target_candidates) candidates = targetConflicts(space_, current);
        for (const AgentConflict& c : earliest) {
          if (std::none_of(candidates.begin(), candidates.end(), [&](const AgentConflict& d) {
                return d.a == c.a && d.b == c.b && d.t == c.t && d.kind == c.kind;
              }))
            candidates.push_back(c);
        }
        bool adopted = false;
        for (const AgentConflict& conflict : candidates) {
          EvaluatedSplit split;
          const Outcome outcome = evaluate(id, current, bounds, conflict, split);
          if (outcome == Outcome::Expired) return stopped();
          if (outcome == Outcome::Adopted) {
            adopted = true;
            break;
          }
          if (!chosen || split.raising > chosen->raising) chosen = std::move(split);
          if (chosen->raising == 2) break;
        }
        if (adopted) chosen.reset();
      }
      for (auto& child : chosen->children) push(std::move(child));
      if (memoryMb() > options_.max_memory_mb) {
        return failure(SolveStatus::Timeout, "constraint tree reached its memory limit of " +
                                                 std::to_string(static_cast<int>(options_.max_memory_mb)) + " MB");
      }
    }
    if (hit_limit_) return failure(SolveStatus::Timeout, "low-level search reached its node limit");
    return failure(SolveStatus::Infeasible, "constraint tree exhausted: no conflict-free plan");
  }

  SolveStats stats() const { return stats_; }
  /// A lower bound on the sum of costs of the searched agents in any plan without conflicts
  /// among them: the optimum after success, the best open node's after the node limit.
  long long lowerBound() const { return lower_bound_; }
  /// Some low-level search stopped at its node limit (its subtree was dropped unexplored).
  bool hitLimit() const { return hit_limit_; }

 private:
  enum class Outcome { Evaluated, Adopted, Expired };

  // Plans both branches of `conflict` at node `id` (whose paths are `current`) into `split`.
  // Bypass (Boyarski et al. 2015): a child path that costs the same and conflicts less is
  // adopted by the node itself (it satisfies a superset of the node's constraints): Adopted.
  Outcome evaluate(int id, std::vector<StatePath>& current, const std::vector<int>& bounds,
                   const AgentConflict& conflict, EvaluatedSplit& split) {
    for (CbsBranch& branch : splitConflict(space_, current, conflict)) {
      const int agent = branch.replan;
      AgentConstraints constraints = constraintsOf(id, agent);
      for (const CbsConstraint& c : branch.constraints) {
        if (c.agent == agent) applyConstraint(space_, c, constraints);
      }
      LowLevelResult ll = lowLevel(agent, constraints, current);
      if (ll.outcome == LowLevelResult::Outcome::Expired) return Outcome::Expired;
      if (ll.outcome == LowLevelResult::Outcome::NodeLimit) hit_limit_ = true;
      if (ll.outcome != LowLevelResult::Outcome::Found) {
        ++split.raising;
        continue;
      }
      const StatePath old = std::move(current[agent]);
      current[agent] = ll.path;
      CtNode child;
      child.parent = id;
      child.constraints = std::move(branch.constraints);
      child.cost = nodes_[id].cost - pathCost(old) + pathCost(ll.path);
      // More constraints: the agent's bound cannot fall below the node's.
      const int child_bound = std::max(bounds[agent], ll.lower_bound);
      child.bound_sum = nodes_[id].bound_sum - bounds[agent] + child_bound;
      const ConflictTally tally = tallyConflicts(space_, current);
      child.count(tally);
      child.f = nodes_[id].f;  // a subtree of the node's: its bound holds
      std::vector<int> child_bounds = bounds;
      child_bounds[agent] = child_bound;
      if (!boundNode(child, tally.pairs, child_bounds)) return Outcome::Expired;
      if (options_.bypass && child.cost == nodes_[id].cost && child.conflicts < nodes_[id].conflicts) {
        replacePath(nodes_[id], agent, ll.path, bounds[agent]);  // the node's bound still holds
        nodes_[id].conflicts = child.conflicts;
        nodes_[id].pairs = child.pairs;
        return Outcome::Adopted;
      }
      current[agent] = std::move(old);
      if (child.cost > nodes_[id].cost) ++split.raising;
      child.paths.emplace_back(agent, std::move(ll.path));
      child.path_bounds.push_back(child_bound);
      split.children.push_back(std::move(child));
    }
    return Outcome::Evaluated;
  }

  // Raises node.f to the agents' lower bounds (`bounds`: their costs unless focal) plus the
  // pairwise delay heuristic on them, first bounding the pairs that conflict in the node's paths
  // (`conflicting`) and have no bound yet; the pairs' searches are optimal. The heuristic holds
  // on lower bounds as on costs: agents that together need B cost at least B in any plan below.
  // False if the deadline came.
  bool boundNode(CtNode& node, const std::vector<std::pair<int, int>>& conflicting, const std::vector<int>& bounds) {
    node.f = std::max(node.f, node.bound_sum);
    if (!pairs_) return true;
    for (const auto& [i, j] : conflicting) {
      if (pairs_->known(i, j)) continue;
      // The pair bounds may spend as many low-level expansions as the tree itself, plus a base.
      const long long allowance = stats_.low_level_expansions - 2 * pair_expansions_ +
                                  options_.pairwise_delay_expansions;
      if (allowance <= 0) break;  // bounded later, if the tree gets that far
      CbsSearch pair(space_, problem_, pair_options_, i, j, options_.pairwise_delay_nodes, allowance);
      const SolveResult r = pair.run();
      stats_.low_level_expansions += pair.stats().low_level_expansions;
      pair_expansions_ += pair.stats().low_level_expansions;
      if (r.status == SolveStatus::Cancelled || problem_.deadline.expired()) return false;
      // A low-level node limit may have cut off cheaper plans: then the bound proves nothing.
      if (!pair.hitLimit()) pairs_->set(i, j, pair.lowerBound());
      else pairs_->set(i, j, 0);
    }
    std::vector<int> least(n_, 0);
    for (const int a : active_) least[a] = bounds[a];
    node.f = std::max(node.f, node.bound_sum + pairs_->heuristic(least));
    return true;
  }

  bool focal() const { return options_.suboptimality > 1.0; }

  // ECBS's primal step (path_around_others.h), also of an anytime search: when every conflict
  // in `current` is between one pair not tried before, each of the two planned around everybody
  // else's paths; at weight 1, when the conflicts are of fewer pairs than at any node before, the
  // conflicting agents planned around the others in turn (a focal tree finds plans without
  // conflicts itself, and its slower searches leave no time for these). Each plan so made is
  // offered as the incumbent. `pair_count`: the number of conflicting pairs in `current`.
  void tryAroundOthers(const std::vector<StatePath>& current, int pair_count) {
    if ((!focal() && !options_.anytime) || !options_.around_others || active_.size() < static_cast<std::size_t>(n_))
      return;
    if (!focal() && pair_count > 1 && pair_count < fewest_pairs_) {
      fewest_pairs_ = pair_count;
      offer(aroundOthersInTurn(space_, current, problem_.deadline, options_.max_low_level_nodes,
                               stats_.low_level_expansions));
      return;
    }
    if (pair_count != 1) return;
    const std::vector<std::pair<int, int>> pairs = conflictingPairs(space_, current);
    if (!tried_pairs_.insert(pairs[0]).second) return;
    for (const int a : {pairs[0].first, pairs[0].second}) {
      const LowLevelResult r = pathAroundOthers(space_, a, current, problem_.deadline, options_.max_low_level_nodes);
      stats_.low_level_expansions += r.expansions;
      if (r.outcome != LowLevelResult::Outcome::Found) continue;
      std::vector<StatePath> plan = current;
      plan[a] = r.path;
      offer(std::move(plan));
    }
  }
  // A plan (none if empty) becomes the incumbent if it has no conflict and costs less.
  void offer(std::vector<StatePath> plan) {
    if (plan.empty()) return;
    long long cost = 0;
    for (const int b : active_) cost += pathCost(plan[b]);
    if ((incumbent_ && cost >= incumbent_cost_) || countConflicts(space_, plan) > 0) return;
    incumbent_ = std::move(plan);
    incumbent_cost_ = cost;
  }
  // The incumbent costs at most the weight times the least lower bound: within the weight of
  // the optimum.
  bool incumbentGoodEnough() const {
    return incumbent_ && static_cast<double>(incumbent_cost_) <=
                             options_.suboptimality * static_cast<double>(lower_bound_);
  }
  static LaCbsOptions optimal(LaCbsOptions o) {
    o.suboptimality = 1.0;
    o.anytime = false;
    return o;
  }

  LowLevelResult lowLevel(int agent, const AgentConstraints& constraints, const std::vector<StatePath>& others) {
    LowLevelOptions o;
    o.max_nodes = std::min(options_.max_low_level_nodes, options_.conflict_aware_nodes);
    const ConflictAvoidanceTable cat(space_, others, agent);
    o.conflicts = [&cat](StateId s, Action act, int t) { return cat.conflicts(s, act, t); };
    if (focal()) {  // ECBS's low level: fewest conflicts within the weight, no second search
      o.max_nodes = options_.max_low_level_nodes;
      o.focal_weight = options_.suboptimality;
      LowLevelResult ll = spaceTimeAStar(space_, agent, constraints, problem_.deadline, o);
      stats_.low_level_expansions += ll.expansions;
      return ll;
    }
    LowLevelResult ll = spaceTimeAStar(space_, agent, constraints, problem_.deadline, o);
    stats_.low_level_expansions += ll.expansions;
    if (ll.outcome == LowLevelResult::Outcome::NodeLimit && o.max_nodes < options_.max_low_level_nodes) {
      o.max_nodes = options_.max_low_level_nodes;
      o.conflicts = nullptr;
      ll = spaceTimeAStar(space_, agent, constraints, problem_.deadline, o);
      stats_.low_level_expansions += ll.expansions;
    }
    return ll;
  }

  AgentConstraints constraintsOf(int id, int agent) const {
    AgentConstraints constraints;
    for (int i = id; i >= 0; i = nodes_[i].parent) {
      for (const CbsConstraint& c : nodes_[i].constraints) {
        if (c.agent == agent) applyConstraint(space_, c, constraints);
      }
    }
    return constraints;
  }

  // The paths of node `id` and, into `bounds`, the lower bounds on their costs.
  std::vector<StatePath> pathsOf(int id, std::vector<int>& bounds) const {
    std::vector<StatePath> paths(n_);
    bounds.assign(n_, 0);
    std::vector<bool> have(n_, false);
    for (int i = id; i >= 0; i = nodes_[i].parent) {
      for (std::size_t k = 0; k < nodes_[i].paths.size(); ++k) {
        const auto& [agent, path] = nodes_[i].paths[k];
        if (!have[agent]) {
          paths[agent] = path;
          bounds[agent] = nodes_[i].path_bounds[k];
          have[agent] = true;
        }
      }
    }
    return paths;
  }

  void replacePath(CtNode& node, int agent, const StatePath& path, int bound) {
    for (std::size_t k = 0; k < node.paths.size(); ++k) {
      auto& [a, p] = node.paths[k];
      if (a == agent) {
        stored_states_ += static_cast<long long>(path.size()) - static_cast<long long>(p.size());
        p = path;
        node.path_bounds[k] = bound;
        return;
      }
    }
    stored_states_ += static_cast<long long>(path.size());
    node.paths.emplace_back(agent, path);
    node.path_bounds.push_back(bound);
  }

  void push(CtNode node) {
    for (const auto& [a, p] : node.paths) stored_states_ += static_cast<long long>(p.size());
    nodes_.push_back(std::move(node));
    open_.push(static_cast<int>(nodes_.size()) - 1);
  }

  double memoryMb() const {
    return (static_cast<double>(stored_states_) * sizeof(StateId) + nodes_.size() * sizeof(CtNode)) / 1048576.0;
  }

  SolveResult success(const std::vector<StatePath>& paths) {
    SolveResult r;
    if (active_.size() < static_cast<std::size_t>(n_)) {  // a pair bound: no poses needed
      r.status = SolveStatus::Success;
      return r;
    }
    r.status = SolveStatus::Success;
    r.paths = toPosePaths(space_, paths);
    return r;
  }
  SolveResult failure(SolveStatus status, std::string reason) const { return failedResult(status, std::move(reason)); }
  SolveResult stopped() const {
    return failure(problem_.deadline.cancelled() ? SolveStatus::Cancelled : SolveStatus::Timeout,
                   problem_.deadline.cancelled() ? "cancelled" : "time limit reached");
  }
  SolveResult lowLevelFailure(int agent, const LowLevelResult& ll, bool root) const {
    switch (ll.outcome) {
      case LowLevelResult::Outcome::Expired:
        return stopped();
      case LowLevelResult::Outcome::NodeLimit:
        return failure(SolveStatus::Timeout, space_.label(agent) + ": low-level search reached its node limit");
      default:
        return failure(SolveStatus::Infeasible,
                       space_.label(agent) + (root ? ": no path that avoids the other subproblems' robots"
                                                   : ": no path under its constraints"));
    }
  }

  const SearchSpace& space_;
  const Subproblem& problem_;
  const LaCbsOptions& options_;
  const LaCbsOptions pair_options_ = optimal(options_);  // the pair bounds' searches
  const int n_;
  std::vector<int> active_;                 // the agents searched; the others have empty paths
  std::optional<PairwiseDelayBound> pairs_;  // top-level search only
  long long max_nodes_ = -1;                 // pair bounds, or the options' budgets
  long long max_expansions_ = -1;            // likewise
  long long pair_expansions_ = 0;            // spent on pair bounds (also in stats_)
  long long lower_bound_ = 0;
  std::vector<CtNode> nodes_;
  TreeFrontier<CtNode> open_{nodes_, options_.suboptimality};
  SolveStats stats_;
  long long stored_states_ = 0;
  bool hit_limit_ = false;
  std::set<std::pair<int, int>> tried_pairs_;       // planned around the others (primal step)
  std::optional<std::vector<StatePath>> incumbent_;  // the cheapest conflict-free plan so far
  long long incumbent_cost_ = 0;
  int fewest_pairs_ = std::numeric_limits<int>::max();  // at the last repair in turn
};

}  // namespace

SolveResult LaCbs::solve(const Subproblem& problem) {
  (void)kRegistered;
  LaCbsOptions options = options_;
  if (problem.max_expansions >= 0) {
    options.max_low_level_nodes = std::min(options.max_low_level_nodes, problem.max_expansions);
    options.max_total_expansions = options.max_total_expansions < 0
                                       ? problem.max_expansions
                                       : std::min(options.max_total_expansions, problem.max_expansions);
    options.pairwise_delay_expansions = std::min(options.pairwise_delay_expansions, problem.max_expansions);
  }
  return solveWith(problem, /*moving_allowed=*/true, [&](const SearchSpace& space, SolveStats& stats) {
    CbsSearch search(space, problem, options);
    SolveResult r = search.run();
    stats = search.stats();
    return r;
  });
}

}  // namespace fleet_planner
