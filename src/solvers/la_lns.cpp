// LA-LNS; see la_lns.h for the reference.
#include "fleet_planner/solvers/la_lns.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <set>
#include <utility>

#include "fleet_planner/core/random.h"
#include "fleet_planner/solvers/joint_path_search.h"
#include "fleet_planner/solvers/joint_repair.h"
#include "fleet_planner/solvers/la_lacam.h"
#include "fleet_planner/solvers/neighborhood_growth.h"
#include "fleet_planner/solvers/ordered_repair.h"
#include "fleet_planner/solvers/path_splice.h"
#include "fleet_planner/solvers/registry.h"
#include "fleet_planner/solvers/safe_interval_search.h"
#include "fleet_planner/solvers/soft_path_search.h"
#include "fleet_planner/solvers/solve_common.h"
#include "fleet_planner/solvers/space_time_astar.h"

namespace fleet_planner {

namespace {

const bool kRegistered = registerSolver("la_lns", [] { return std::make_unique<LaLns>(); });

enum Method { kCollisionGraph = 0, kIdealPath = 1, kRandom = 2, kJoint = 3, kMethods = 4 };

class LnsSearch {
 public:
  LnsSearch(const SearchSpace& space, const Subproblem& problem, const LaLnsOptions& options,
            SolveStats& stats)
      : space_(space),
        problem_(problem),
        options_(options),
        stats_(stats),
        n_(space.numAgents()),
        table_(space),
        rng_(problem.seed),
        partners_(n_),
        ideal_(n_),
        ideal_absent_(n_, false),
        escalation_(n_, 1),
        growth_(options.neighborhood_size, options.stall_repairs, n_) {
    weights_.fill(1.0);
  }

  SolveResult run() {
    std::vector<int> order(n_);
    std::iota(order.begin(), order.end(), 0);
    // Longest first: the agents with most to do get the freest space.
    std::stable_sort(order.begin(), order.end(), [&](int x, int y) {
      return space_.distance(x, space_.start(x)) > space_.distance(y, space_.start(y));
    });
    for (int a : order) {
      StatePath path;
      if (std::optional<SolveResult> stop = initialPath(a, path)) return *stop;
      table_.insert(a, path);
      ++planned_;
    }
    for (int a = 0; a < n_; ++a) partners_[a] = table_.partners(a);
    while (true) {
      if (collidingPairs() == 0) {
        // The table's answer, checked by the backends' own conflict code before it is returned.
        std::vector<StatePath> paths(n_);
        for (int a = 0; a < n_; ++a) paths[a] = table_.path(a);
        const std::optional<AgentConflict> c = firstConflict(space_, paths);
        if (!c) return success(paths);
        link(c->a, c->b);
      }
      if (std::optional<SolveResult> stop = outOfBudget()) return *stop;
      repair();
      if (proof_) {
        SolveResult r = failedResult(SolveStatus::Infeasible, *proof_);
        r.culprits = proof_culprits_;
        return r;
      }
    }
  }

 private:
  std::optional<SolveResult> outOfBudget() const {
    if (problem_.deadline.cancelled()) return failedResult(SolveStatus::Cancelled, "cancelled");
    if (problem_.deadline.expired()) return timeout("time limit reached");
    if (problem_.max_expansions >= 0 && stats_.low_level_expansions > problem_.max_expansions)
      return timeout("expansion budget of " + std::to_string(problem_.max_expansions) + " used up");
    return std::nullopt;
  }

  SolveResult timeout(const std::string& why) const {
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
  std::string somePairs() const {
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
  std::optional<SolveResult> initialPath(int a, StatePath& path) {
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
  SoftSearchResult search(int a) {
    // A collision-free path first (safe intervals: long waits are cheap there), if there is one.
    const SafeIntervalResult free = safeIntervalSearch(space_, a, table_, problem_.deadline,
                                                       options_.max_expansions_per_search);
    stats_.low_level_expansions += free.expansions;
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
    SoftSearchResult r = softPathSearch(space_, a, table_, problem_.deadline, o);
    stats_.low_level_expansions += r.expansions;
    if (r.outcome == SoftSearchResult::Outcome::Found) {
      escalation_[a] = r.collisions == 0 ? 1 : std::min(escalation_[a] * 2, 64);
    } else if (r.outcome == SoftSearchResult::Outcome::NodeLimit) {
      escalation_[a] = std::max(escalation_[a] / 2, 1);
    }
    return r;
  }

  // Shortest path of a around hard obstacles only (empty if none or out of time); cached.
  const StatePath& idealPath(int a) {
    if (ideal_[a].empty() && !ideal_absent_[a]) {
      const LowLevelResult r = spaceTimeAStar(space_, a, AgentConstraints{}, problem_.deadline);
      stats_.low_level_expansions += r.expansions;
      if (r.outcome == LowLevelResult::Outcome::Found) ideal_[a] = r.path;
      ideal_absent_[a] = r.outcome == LowLevelResult::Outcome::NoPath;
    }
    return ideal_[a];
  }

  int collidingPairs() const {
    std::size_t ends = 0;
    for (const auto& p : partners_) ends += p.size();
    return static_cast<int>(ends / 2);
  }

  void link(int a, int b) {
    auto add = [](std::vector<int>& v, int x) {
      const auto it = std::lower_bound(v.begin(), v.end(), x);
      if (it == v.end() || *it != x) v.insert(it, x);
    };
    add(partners_[a], b);
    add(partners_[b], a);
  }

  int pick(const std::vector<int>& from) {
    return from[rng_.uniformInt(0, static_cast<std::int64_t>(from.size()) - 1)];
  }

  void shuffle(std::vector<int>& v) {
    for (std::size_t i = v.size(); i > 1; --i)
      std::swap(v[i - 1], v[rng_.uniformInt(0, static_cast<std::int64_t>(i) - 1)]);
  }

  Method chooseMethod() {
    double total = 0;
    for (double w : weights_) total += w;
    double r = rng_.uniform01() * total;
    for (int m = 0; m < kMethods; ++m) {
      if ((r -= weights_[m]) < 0) return static_cast<Method>(m);
    }
    return kRandom;
  }

  std::vector<int> neighborhood(Method method) {
    const int k = std::min(size_, n_);
    std::vector<int> colliding;
    for (int a = 0; a < n_; ++a) {
      if (!partners_[a].empty()) colliding.push_back(a);
    }
    if (k >= n_) {
      std::vector<int> all(n_);
      std::iota(all.begin(), all.end(), 0);
      return all;
    }
    std::vector<int> chosen;
    std::vector<bool> in(n_, false);
    auto take = [&](int a) {
      if (!in[a] && static_cast<int>(chosen.size()) < k) {
        in[a] = true;
        chosen.push_back(a);
      }
    };
    const int seed_agent = pick(colliding);
    take(seed_agent);
    if (method == kCollisionGraph) {
      // Breadth-first over the collision graph, then a random walk on it to widen a small one.
      for (std::size_t head = 0; head < chosen.size(); ++head) {
        std::vector<int> next = partners_[chosen[head]];
        shuffle(next);
        for (int b : next) take(b);
      }
      for (int step = 0, a = seed_agent; step < 4 * k && static_cast<int>(chosen.size()) < k;
           ++step) {
        const StatePath& ideal = idealPath(a);
        if (ideal.empty()) break;
        const std::vector<int> in_way = table_.partners(a, ideal);
        if (in_way.empty()) break;
        a = pick(in_way);
        take(a);
      }
    } else if (method == kIdealPath) {
      // The agents in the way of the seed agent's ideal path.
      const StatePath& ideal = idealPath(seed_agent);
      if (!ideal.empty()) {
        std::vector<int> in_way = table_.partners(seed_agent, ideal);
        shuffle(in_way);
        for (int b : in_way) take(b);
      }
    }
    // Fill up with random colliding agents (the random method takes only these).
    shuffle(colliding);
    for (int a : colliding) take(a);
    return chosen;
  }

  // Colliding pairs with at least one agent of `group`, given each agent's partners.
  static int pairsTouching(const std::vector<int>& group,
                           const std::vector<std::vector<int>>& partners,
                           const std::vector<bool>& in) {
    int count = 0;
    for (int a : group) {
      for (int b : partners[a]) count += (!in[b] || a < b) ? 1 : 0;
    }
    return count;
  }

  // Replans the group robot by robot (each around all others); false if a search gave up.
  bool planOneByOne(const std::vector<int>& group) {
    for (int a : group) {
      SoftSearchResult r = search(a);
      if (r.outcome != SoftSearchResult::Outcome::Found) return false;
      table_.insert(a, r.path);
    }
    return true;
  }

  // Replans the group jointly around all others' paths: first one after the other, in the
  // group's order and then in reverse, with the members not yet replanned at their starts
  // (ordered_repair.h: cheap, and collision-free if it works); then by LA-CBS within a small
  // share of the time left (others hard), and if that finds nothing, for a small group and once the
  // neighbourhood has grown to the whole subproblem, by a joint search (joint_path_search.h;
  // others soft); false if neither found a plan. A joint search that exhausts the group's joint
  // space proves that the subproblem has no plan (proof_). The joint search waits for the deep
  // stall because it costs time the repair needs: run at every joint step, its budget spent
  // 4-5 s of the 7 s that LA-LNS had for a 12-robot level of maze-128-128-10 K=40, which it
  // otherwise solves in that time.
  bool planTogether(const std::vector<int>& group) {
    for (const std::vector<int>& order : {group, std::vector<int>(group.rbegin(), group.rend())}) {
      const std::optional<std::vector<StatePath>> paths =
          orderedRepair(space_, table_, order, problem_.deadline,
                        options_.max_expansions_per_search, stats_.low_level_expansions);
      if (!paths) continue;
      for (std::size_t k = 0; k < order.size(); ++k) table_.insert(order[k], (*paths)[k]);
      return true;
    }
    const double seconds = std::min(options_.joint_seconds, problem_.deadline.remaining() / 4);
    const std::vector<StatePath> paths =
        jointRepair(space_, problem_, table_, group, seconds, options_.joint_max_expansions,
                    rng_.next(), stats_.low_level_expansions);
    for (std::size_t k = 0; k < paths.size(); ++k) table_.insert(group[k], paths[k]);
    if (!paths.empty()) return true;
    if (static_cast<int>(group.size()) > kMaxJointGroup || size_ < n_) return false;
    JointSearchOptions o;
    o.collision_cost = options_.collision_cost;
    o.max_nodes = options_.joint_search_nodes;
    const JointSearchResult r = jointPathSearch(space_, group, table_, problem_.deadline, o);
    stats_.low_level_expansions += r.expansions;
    if (r.outcome == JointSearchResult::Outcome::Found) {
      for (std::size_t k = 0; k < group.size(); ++k) table_.insert(group[k], r.paths[k]);
      return true;
    }
    if (r.outcome == JointSearchResult::Outcome::NoPath) {
      std::vector<int> sorted = group;
      std::sort(sorted.begin(), sorted.end());
      std::string names;
      for (std::size_t k = 0; k < sorted.size(); ++k)
        names += (k == 0 ? "" : k + 1 == sorted.size() ? " and " : ", ") + space_.label(sorted[k]);
      proof_culprits_.clear();
      for (int a : sorted) proof_culprits_.push_back(space_.robot(a));
      proof_ = names + " cannot all reach their targets around the obstacles they must avoid " +
               "(their joint search ran out of states)";
      return false;
    }
    provePair(group);
    return false;
  }

  // A pair of the knot that cannot reach its targets even alone among the static obstacles
  // proves that the subproblem has no plan (proof_): dropping robots and obstacles only makes a
  // problem easier. LA-LaCAM decides the pair (its search over configurations is complete); the
  // joint search above rarely exhausts its timed joint space, and the pair's configurations are
  // far fewer. Each pair is tried once.
  void provePair(const std::vector<int>& group) {
    for (std::size_t i = 0; i < group.size() && !proof_; ++i) {
      for (std::size_t j = i + 1; j < group.size() && !proof_; ++j) {
        const int a = std::min(group[i], group[j]), b = std::max(group[i], group[j]);
        if (!pairs_tried_.insert({a, b}).second) continue;
        Subproblem pair;  // no moving obstacles, no other robot of this subproblem
        pair.instance = problem_.instance;
        pair.graphs = problem_.graphs;
        pair.robots = {space_.robot(a), space_.robot(b)};
        pair.blocked = problem_.blocked;
        pair.returning = problem_.returning;
        pair.deadline = problem_.deadline.within(problem_.deadline.remaining() / 8);
        pair.max_expansions = options_.pair_proof_expansions;
        const SolveResult r = LaLacam().solve(pair);
        stats_.low_level_expansions += r.stats.low_level_expansions;
        if (r.status != SolveStatus::Infeasible) continue;
        proof_culprits_ = pair.robots;
        proof_ = space_.label(a) + " and " + space_.label(b) +
                 " cannot both reach their targets around the obstacles they must avoid, even " +
                 "with no other robot moving (" + r.reason + ")";
      }
    }
  }

  // A colliding agent and up to joint_size - 1 of its partners.
  std::vector<int> knot() {
    std::vector<int> colliding;
    for (int a = 0; a < n_; ++a) {
      if (!partners_[a].empty()) colliding.push_back(a);
    }
    const int a = pick(colliding);
    std::vector<int> others = partners_[a];
    shuffle(others);
    others.resize(
        std::min<std::size_t>(others.size(), static_cast<std::size_t>(options_.joint_size - 1)));
    others.insert(others.begin(), a);
    return others;
  }

  // Replaces agent a's path in the table and its edges in the collision graph (`partners`:
  // the agents the new path collides with).
  void replacePath(int a, const StatePath& path, const std::vector<int>& partners) {
    table_.remove(a);
    table_.insert(a, path);
    for (int b : partners_[a])
      partners_[b].erase(std::lower_bound(partners_[b].begin(), partners_[b].end(), a));
    partners_[a].clear();
    for (int b : partners) link(a, b);
  }

  // One local repair (path_splice.h) of a random collision of a random colliding agent, kept
  // unless the delay it gives the rest of the path meets more agents than before.
  void splice() {
    std::vector<int> colliding;
    for (int a = 0; a < n_; ++a) {
      if (!partners_[a].empty()) colliding.push_back(a);
    }
    if (colliding.empty()) return;
    const int a = pick(colliding);
    const std::vector<int> starts = collisionStarts(space_, a, table_);
    if (starts.empty()) return;
    const SpliceResult r = spliceAround(space_, a, table_, pick(starts), /*delays=*/true,
                                        problem_.deadline, options_.max_expansions_per_search);
    stats_.low_level_expansions += r.expansions;
    if (!r.path) return;
    const std::vector<int> partners = table_.partners(a, *r.path);
    if (partners.size() <= partners_[a].size()) replacePath(a, *r.path, partners);
  }

  void repair() {
    ++stats_.high_level_nodes;
    if (options_.splice) {
      splice();
      if (collidingPairs() == 0) return;
    }
    size_ = growth_.next(collidingPairs());
    const Method method = chooseMethod();
    std::vector<int> group = method == kJoint ? knot() : neighborhood(method);
    std::vector<bool> in(n_, false);
    for (int a : group) in[a] = true;
    const int before = pairsTouching(group, partners_, in);

    const std::vector<int> members = group;
    std::vector<StatePath> old(group.size());
    for (std::size_t i = 0; i < group.size(); ++i) {
      old[i] = table_.path(group[i]);
      table_.remove(group[i]);
    }
    shuffle(group);
    const bool planned = method == kJoint ? planTogether(group) : planOneByOne(group);
    std::vector<std::vector<int>> fresh(n_);
    int after = before + 1;
    if (planned) {
      for (int a : group) fresh[a] = table_.partners(a);
      after = pairsTouching(group, fresh, in);
    }
    weights_[method] = 0.1 * std::max(0, before - after) / static_cast<double>(group.size()) +
                       0.9 * weights_[method];
    weights_[method] = std::max(weights_[method], 0.01);
    if (after <= before) {
      for (int a : group) {
        for (int b : partners_[a]) {
          if (!in[b])
            partners_[b].erase(std::lower_bound(partners_[b].begin(), partners_[b].end(), a));
        }
      }
      for (int a : group) partners_[a].clear();
      for (int a : group) {
        for (int b : fresh[a]) link(a, b);
      }
      return;
    }
    // Not better: put the old paths back.
    for (std::size_t i = 0; i < members.size(); ++i) {
      if (table_.contains(members[i])) table_.remove(members[i]);
      table_.insert(members[i], old[i]);
    }
  }

  SolveResult success(const std::vector<StatePath>& paths) const {
    SolveResult r;
    r.status = SolveStatus::Success;
    r.paths = toPosePaths(space_, paths);
    return r;
  }

  const SearchSpace& space_;
  const Subproblem& problem_;
  const LaLnsOptions& options_;
  SolveStats& stats_;
  const int n_;
  SoftPathTable table_;
  Rng rng_;
  std::vector<std::vector<int>> partners_;  // sorted; symmetric: the collision graph
  std::vector<StatePath> ideal_;
  std::vector<bool> ideal_absent_;  // the search proved there is no such path
  std::vector<int> escalation_;     // per agent: factor of the collision cost
  int planned_ = 0;                 // robots with a path in the first plan so far
  std::optional<std::string> proof_;  // why the subproblem has no plan, once a search proved it
  std::vector<int> proof_culprits_;   // the robots of that proof (instance indices)
  std::set<std::pair<int, int>> pairs_tried_;  // by provePair
  NeighborhoodGrowth growth_;
  int size_ = 0;                    // agents in this repair's neighbourhood (growth_)
  std::array<double, kMethods> weights_;
};

}  // namespace

SolveResult LaLns::solve(const Subproblem& problem) {
  (void)kRegistered;
  return solveWith(problem, /*moving_allowed=*/true,
                   [&](const SearchSpace& space, SolveStats& stats) {
                     LnsSearch search(space, problem, options_, stats);
                     return search.run();
                   });
}

}  // namespace fleet_planner
