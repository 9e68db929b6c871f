// LA-CBS; see la_cbs.h for the references.
#include "fleet_planner/solvers/la_cbs.h"

#include <algorithm>
#include <chrono>
#include <queue>

#include "fleet_planner/core/errors.h"
#include "fleet_planner/solvers/agent_conflicts.h"
#include "fleet_planner/solvers/registry.h"
#include "fleet_planner/solvers/solve_common.h"
#include "fleet_planner/solvers/space_time_astar.h"

namespace fleet_planner {

namespace {

const bool kRegistered = registerSolver("la_cbs", [] { return std::make_unique<LaCbs>(); });

// The agent must not cover `cell` at time t (At) or during step t (During).
struct Constraint {
  enum class Kind { None, At, During };
  Kind kind = Kind::None;
  int agent = -1;
  Cell cell;
  int t = 0;
};

// A constraint-tree node stores only what it changes: its constraint and the paths it replanned.
struct CtNode {
  int parent = -1;
  Constraint constraint;
  std::vector<std::pair<int, StatePath>> paths;
  long long cost = 0;
  int conflicts = 0;
};

int pathCostOf(const StatePath& p) {
  int t = static_cast<int>(p.size()) - 1;
  while (t > 0 && p[t - 1] == p.back()) --t;
  return t;
}

class CbsSearch {
 public:
  CbsSearch(const SearchSpace& space, const Subproblem& problem, const LaCbsOptions& options)
      : space_(space), problem_(problem), options_(options), n_(space.numAgents()) {}

  SolveResult run() {
    SolveResult result;
    CtNode root;
    std::vector<StatePath> paths(n_);
    for (int a = 0; a < n_; ++a) {
      const AgentConstraints none;
      LowLevelResult ll = lowLevel(a, none, paths);
      if (ll.outcome != LowLevelResult::Outcome::Found) return lowLevelFailure(a, ll, true);
      paths[a] = std::move(ll.path);
    }
    for (int a = 0; a < n_; ++a) {
      root.cost += pathCostOf(paths[a]);
      root.paths.emplace_back(a, paths[a]);
    }
    root.conflicts = countConflicts(space_, paths);
    push(std::move(root));

    while (!open_.empty()) {
      if (problem_.deadline.expired()) return stopped();
      const int id = open_.top();
      open_.pop();
      ++stats_.high_level_nodes;
      std::vector<StatePath> current = pathsOf(id);
      bool adopted = true;
      while (adopted) {  // bypass may adopt paths and look again at the same node
        adopted = false;
        const auto conflict = firstConflict(space_, current);
        if (!conflict) return success(current);
        if (conflict->t == 0 && conflict->kind == AgentConflict::Kind::Vertex) {
          return failure(SolveStatus::Infeasible,
                         space_.label(conflict->a) + " and " + space_.label(conflict->b) + " overlap at their starts");
        }
        std::vector<CtNode> children;
        for (int side = 0; side < 2; ++side) {
          const int agent = side == 0 ? conflict->a : conflict->b;
          Constraint c;
          c.agent = agent;
          c.t = conflict->t;
          c.cell = conflict->cell;
          c.kind = conflict->kind == AgentConflict::Kind::Vertex ? Constraint::Kind::At : Constraint::Kind::During;
          AgentConstraints constraints = constraintsOf(id, agent);
          apply(constraints, c);
          LowLevelResult ll = lowLevel(agent, constraints, current);
          if (ll.outcome == LowLevelResult::Outcome::Expired) return stopped();
          if (ll.outcome == LowLevelResult::Outcome::NodeLimit) hit_limit_ = true;
          if (ll.outcome != LowLevelResult::Outcome::Found) continue;
          std::vector<StatePath> next = current;
          next[agent] = ll.path;
          CtNode child;
          child.parent = id;
          child.constraint = c;
          child.cost = nodes_[id].cost - pathCostOf(current[agent]) + pathCostOf(ll.path);
          child.conflicts = countConflicts(space_, next);
          if (options_.bypass && child.cost == nodes_[id].cost && child.conflicts < nodes_[id].conflicts) {
            // Bypass: the node may hold this path too, it satisfies a superset of its constraints.
            replacePath(nodes_[id], agent, ll.path);
            nodes_[id].conflicts = child.conflicts;
            current = std::move(next);
            adopted = true;
            break;
          }
          child.paths.emplace_back(agent, std::move(ll.path));
          children.push_back(std::move(child));
        }
        if (!adopted) {
          for (auto& child : children) push(std::move(child));
        }
      }
      if (memoryMb() > options_.max_memory_mb) {
        return failure(SolveStatus::Timeout, "constraint tree reached its memory limit of " +
                                                 std::to_string(static_cast<int>(options_.max_memory_mb)) + " MB");
      }
    }
    if (hit_limit_) return failure(SolveStatus::Timeout, "low-level search reached its node limit");
    return failure(SolveStatus::Infeasible, "constraint tree exhausted: no conflict-free plan");
  }

  SolveStats stats() const { return stats_; }

 private:
  LowLevelResult lowLevel(int agent, const AgentConstraints& constraints, const std::vector<StatePath>& others) {
    LowLevelOptions o;
    o.max_nodes = options_.max_low_level_nodes;
    const ConflictAvoidanceTable cat(space_, others, agent);
    o.conflicts = [&cat](StateId s, Action act, int t) { return cat.conflicts(s, act, t); };
    LowLevelResult ll = spaceTimeAStar(space_, agent, constraints, problem_.deadline, o);
    stats_.low_level_expansions += ll.expansions;
    return ll;
  }

  static void apply(AgentConstraints& constraints, const Constraint& c) {
    if (c.kind == Constraint::Kind::At) constraints.forbidCellAt(c.cell, c.t);
    if (c.kind == Constraint::Kind::During) constraints.forbidCellDuring(c.cell, c.t);
  }

  AgentConstraints constraintsOf(int id, int agent) const {
    AgentConstraints constraints;
    for (int i = id; i >= 0; i = nodes_[i].parent) {
      if (nodes_[i].constraint.agent == agent) apply(constraints, nodes_[i].constraint);
    }
    return constraints;
  }

  std::vector<StatePath> pathsOf(int id) const {
    std::vector<StatePath> paths(n_);
    std::vector<bool> have(n_, false);
    for (int i = id; i >= 0; i = nodes_[i].parent) {
      for (const auto& [agent, path] : nodes_[i].paths) {
        if (!have[agent]) {
          paths[agent] = path;
          have[agent] = true;
        }
      }
    }
    return paths;
  }

  void replacePath(CtNode& node, int agent, const StatePath& path) {
    for (auto& [a, p] : node.paths) {
      if (a == agent) {
        stored_states_ += static_cast<long long>(path.size()) - static_cast<long long>(p.size());
        p = path;
        return;
      }
    }
    stored_states_ += static_cast<long long>(path.size());
    node.paths.emplace_back(agent, path);
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

  struct Worse {
    const std::vector<CtNode>* nodes;
    bool operator()(int x, int y) const {
      const CtNode &a = (*nodes)[x], &b = (*nodes)[y];
      if (a.cost != b.cost) return a.cost > b.cost;
      if (a.conflicts != b.conflicts) return a.conflicts > b.conflicts;
      return x > y;
    }
  };

  const SearchSpace& space_;
  const Subproblem& problem_;
  const LaCbsOptions& options_;
  const int n_;
  std::vector<CtNode> nodes_;
  std::priority_queue<int, std::vector<int>, Worse> open_{Worse{&nodes_}};
  SolveStats stats_;
  long long stored_states_ = 0;
  bool hit_limit_ = false;
};

}  // namespace

SolveResult LaCbs::solve(const Subproblem& problem) {
  (void)kRegistered;
  return solveWith(problem, /*moving_allowed=*/true, [&](const SearchSpace& space, SolveStats& stats) {
    CbsSearch search(space, problem, options_);
    SolveResult r = search.run();
    stats = search.stats();
    return r;
  });
}

}  // namespace fleet_planner
