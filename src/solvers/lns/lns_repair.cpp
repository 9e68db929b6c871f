// LA-LNS: replanning a neighbourhood; see lns_search.h.
#include <algorithm>
#include <climits>
#include <functional>

#include "fleet_planner/infeasibility/infeasible_pairs.h"
#include "fleet_planner/solvers/lns/joint_repair.h"
#include "fleet_planner/solvers/lacam/la_lacam.h"
#include "fleet_planner/solvers/lns/ordered_repair.h"
#include "fleet_planner/solvers/lns/path_splice.h"
#include "fleet_planner/solvers/lns/pocket_repair.h"
#include "fleet_planner/solvers/search/joint_path_search.h"
#include "fleet_planner/solvers/search/safe_interval_search.h"
#include "fleet_planner/solvers/search/solve_common.h"
#include "lns_search.h"

namespace fleet_planner {

// Replans the group robot by robot (each around all others); false if a search gave up.
bool LnsSearch::planOneByOne(const std::vector<int>& group) {
  for (int a : group) {
    SoftSearchResult r = search(a);
    if (r.outcome != SoftSearchResult::Outcome::Found) return false;
    table_.insert(a, r.path);
  }
  return true;
}

// Replans the group jointly around all others' paths: first one after the other, in the
// group's order and then in reverse, with the members not yet replanned at their starts
// (ordered_repair.h: cheap, and collision-free if it works); then two of them trading places
// through a pocket (pocket_repair.h, collision-free too); then by LA-CBS within a small share
// of the time left (others hard); then alone by LA-LaCAM (planAlone); and if none of these
// finds a plan, for a small group and once the neighbourhood has grown to the whole
// subproblem, by a joint search (joint_path_search.h; others soft); false if none found one. A
// joint search that exhausts the group's joint space proves that the subproblem has no plan
// (proof_). The joint search waits for the deep stall because it costs time the repair needs:
// run at every joint step, its budget spent 4-5 s of the 7 s that LA-LNS had for a 12-robot
// level of maze-128-128-10 K=40, which it otherwise solves in that time. In a large
// subproblem it also runs once per group and number of colliding pairs when at most
// joint_search_pairs pairs are left: a large subproblem's neighbourhood may never grow to all
// of it before its time runs out, while the knot left at its end needs the joint search.
bool LnsSearch::planTogether(const std::vector<int>& group) {
  for (const std::vector<int>& order : {group, std::vector<int>(group.rbegin(), group.rend())}) {
    const std::optional<std::vector<StatePath>> paths =
        orderedRepair(space_, table_, order, problem_->deadline,
                      options_.max_expansions_per_search, stats_->low_level_expansions);
    if (!paths) continue;
    for (std::size_t k = 0; k < order.size(); ++k) table_.insert(order[k], (*paths)[k]);
    return true;
  }
  if (planThroughPocket(group)) return true;
  const double seconds = std::min(options_.joint_seconds, problem_->deadline.remaining() / 4);
  const std::vector<StatePath> paths =
      jointRepair(space_, *problem_, table_, group, seconds, options_.joint_max_expansions,
                  rng_.next(), stats_->low_level_expansions);
  for (std::size_t k = 0; k < paths.size(); ++k) table_.insert(group[k], paths[k]);
  if (!paths.empty()) return true;
  if (planAlone(group, seconds)) return true;
  if (static_cast<int>(group.size()) > kMaxJointGroup) return false;
  std::vector<int> key = group;
  std::sort(key.begin(), key.end());
  if (size_ < n_) {
    const int pairs = collidingPairs();
    if (pairs > options_.joint_search_pairs || !joint_tried_.insert({key, pairs}).second) return false;
  }
  // The joint searches below depend only on the group and the paths in the table: searched
  // again with no path kept since, they would spend their states again for nothing (a small
  // subproblem's repairs are all joint repairs, mostly of the same few groups).
  const auto [last, first_time] = joint_searched_at_.try_emplace(key, kept_);
  if (!first_time) {
    if (last->second == kept_) return false;
    last->second = kept_;
  }
  JointSearchOptions o;
  o.collision_cost = options_.collision_cost;
  o.max_nodes = options_.joint_search_nodes;
  const JointSearchResult r = jointPathSearch(space_, group, table_, problem_->deadline, o);
  stats_->low_level_expansions += r.expansions;
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
  if (r.outcome == JointSearchResult::Outcome::NodeLimit && planTogetherLater(group, o)) return true;
  provePair(group);
  return false;
}

// The last step at which an agent outside the group stands within reach of the box, plus one
// (an agent that ends there counts until its path ends: it stays for good from then on).
int LnsSearch::stillNear(const std::vector<int>& group, const std::vector<StateId>& at, int t0, int lead) const {
  const int reach = (lead + 8) * space_.graph(group[0]).actionModel().step;
  int x0 = INT_MAX, y0 = INT_MAX, x1 = INT_MIN, y1 = INT_MIN;
  for (std::size_t k = 0; k < group.size(); ++k) {
    for (const StateId s : {at[k], space_.target(group[k])}) {
      const GridPose p = space_.graph(group[k]).pose(s);
      x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
    }
  }
  int last = t0;
  for (int b = 0; b < n_; ++b) {
    if (!table_.contains(b) || std::find(group.begin(), group.end(), b) != group.end()) continue;
    const StatePath& path = table_.path(b);
    for (int t = static_cast<int>(path.size()) - 1; t > last; --t) {
      const GridPose p = space_.graph(b).pose(path[t]);
      if (p.x >= x0 - reach && p.x <= x1 + reach && p.y >= y0 - reach && p.y <= y1 + reach) {
        last = t;
        break;
      }
    }
  }
  return last + 1;
}

bool LnsSearch::planTogetherLater(const std::vector<int>& group, JointSearchOptions options) {
  std::vector<StatePath> before(n_);
  for (int a : group) before[a] = joint_before_[a];
  const std::optional<AgentConflict> met = firstConflict(space_, before);
  if (!met) return false;
  const int n = static_cast<int>(group.size());
  // Four times the joint states of the search from step 0: it tries up to 2 x (n + 1) starts,
  // each from closer to the knot, where the states go to the timing of waits.
  options.max_nodes *= 4;
  // Leads of a few dozen steps: enough to make way for each other, few enough to search. At
  // each, the members where their paths have them then, and then each member instead held at
  // its start until then: a robot that drove into a place it cannot leave (a target at a wall
  // it cannot turn at) must wait for the other where it stood.
  for (const int lead : {kLaterLead, 4 * kLaterLead}) {
    const int t0 = met->t - lead;
    if (t0 <= 0) return false;
    for (int held = -1; held < n; ++held) {
      // A member at its start at t0 anyway: holding it there is the search just made.
      if (held >= 0 && stateAt(before[group[held]], t0) == stateAt(before[group[held]], 0)) continue;
      options.from.clear();
      for (int k = 0; k < n; ++k) options.from.push_back(stateAt(before[group[k]], k == held ? 0 : t0));
      options.from_step = t0;
      // First with every step after t0 merged (JointSearchOptions::static_from): the members'
      // configurations, each at its earliest step, few enough to search however long the
      // others drive on nearby; a member cannot wait there for another robot to pass, but each
      // collision still counts at its true step, and the repairs after this one take up what
      // it leaves. Then merged only after the last agent near the group stops (stillNear),
      // where such waits are states of their own.
      std::vector<int> merged_from{t0 + 1};
      const int near = stillNear(group, options.from, t0, lead);
      if (near > t0 + 1) merged_from.push_back(near);
      for (const int static_from : merged_from) {
        options.static_from = static_from;
        const JointSearchResult r = jointPathSearch(space_, group, table_, problem_->deadline, options);
        stats_->low_level_expansions += r.expansions;
        if (r.outcome == JointSearchResult::Outcome::Expired) return false;
        if (r.outcome != JointSearchResult::Outcome::Found) continue;
        const StatePath prefix = held >= 0 ? heldPrefix(group[held], t0) : StatePath{};
        for (int k = 0; k < n; ++k) {
          StatePath path;
          for (int t = 0; t < t0; ++t) path.push_back(stateAt(k == held ? prefix : before[group[k]], t));
          path.insert(path.end(), r.paths[k].begin(), r.paths[k].end());
          table_.insert(group[k], path);
        }
        return true;
      }
    }
  }
  return false;
}

// Agent a's way from its start at step 0 back to it by step t0, held there until t0, around the
// agents in the table (the group's members are not in it while it is repaired): a member held
// at its start for the later search still makes way for the robots that pass it before t0
// (those that leave from beside it, those that drive past it to their targets). Standing at
// its start throughout if there is no such way.
StatePath LnsSearch::heldPrefix(int a, int t0) {
  const StateId start = joint_before_[a][0];
  const SafeIntervalResult r = safeIntervalSegment(space_, a, table_, start, 0, start, t0, 0, problem_->deadline,
                                                   options_.max_expansions_per_search);
  stats_->low_level_expansions += r.expansions;
  if (r.outcome == SafeIntervalResult::Outcome::Found) return r.path;
  return StatePath{start};
}

// LA-LaCAM's search over the group's configurations unties knots of two or three robots in
// an aisle that the searches above miss, one robot at a time (a pair of real robots alone:
// 1,709 configurations where LA-CBS and the soft repairs ran out of time). It sees only the
// static obstacles; the repair keeps its paths only if the colliding pairs do not grow.
bool LnsSearch::planAlone(const std::vector<int>& group, double seconds) {
  if (options_.alone_expansions <= 0 || !problem_->moving.empty()) return false;
  Subproblem sub;
  sub.instance = problem_->instance;
  sub.graphs = problem_->graphs;
  sub.blocked = problem_->blocked;
  sub.returning = problem_->returning;
  for (int a : group) sub.robots.push_back(space_.robot(a));
  sub.deadline = problem_->deadline.within(seconds);
  sub.seed = rng_.next();
  sub.max_expansions = options_.alone_expansions;
  const SolveResult r = LaLacam().solve(sub);
  stats_->low_level_expansions += r.stats.low_level_expansions;
  if (!r.success()) return false;
  const std::vector<StatePath> paths = toStatePaths(space_, group, r.paths);
  for (std::size_t k = 0; k < group.size(); ++k) table_.insert(group[k], paths[k]);
  return true;
}

// Each member of the group in turn drives to its target while the others wait in pockets off
// its way and then drive on, in the group's order (pocket_repair.h). False (and none of the
// group in the table) if no pocket worked. Each time it fails for a group, that group's budget
// doubles (up to 16 times pocket_expansions): a leg that must go round the robot that parked at
// its target expands much of the map (the distances do not see that robot), and most knots
// are untied, or not, within the base budget.
bool LnsSearch::planThroughPocket(const std::vector<int>& group) {
  if (group.size() < 2 || options_.pockets <= 0) return false;
  std::vector<int> key = group;
  std::sort(key.begin(), key.end());
  int& failures = pocket_failures_[key];
  PocketRepairOptions o;
  o.max_pockets = options_.pockets;
  o.max_expansions = options_.pocket_expansions << std::min(failures, 4);
  o.beside_way = true;
  for (int through : group) {
    std::vector<int> parkers;
    for (int a : group) {
      if (a != through) parkers.push_back(a);
    }
    const std::optional<std::vector<StatePath>> paths =
        pocketRepair(space_, table_, through, parkers, idealPath(through), problem_->deadline, o,
                     stats_->low_level_expansions);
    if (!paths) continue;
    table_.insert(through, (*paths)[0]);
    for (std::size_t i = 0; i < parkers.size(); ++i) table_.insert(parkers[i], (*paths)[i + 1]);
    return true;
  }
  ++failures;
  return false;
}

// A pair of the knot that cannot reach its targets even alone among the static obstacles
// proves that the subproblem has no plan (proof_): dropping robots and obstacles only makes a
// problem easier. LA-LaCAM decides the pair (its search over configurations is complete); the
// joint search above rarely exhausts its timed joint space, and the pair's configurations are
// far fewer. Each pair is tried once. Not when the caller may give up (robots of other
// subproblems stand near, Subproblem::may_give_up): their standing footprints are among the
// static obstacles, so a proof would only send the subproblem where giving up sends it too, to
// those robots stepping aside, and 2,000,000 expansions a pair took most of such a knot's time.
void LnsSearch::provePair(const std::vector<int>& group) {
  if (mayGiveUp()) return;
  for (std::size_t i = 0; i < group.size() && !proof_; ++i) {
    for (std::size_t j = i + 1; j < group.size() && !proof_; ++j) {
      const int a = std::min(group[i], group[j]), b = std::max(group[i], group[j]);
      if (!pairs_tried_.insert({a, b}).second) continue;
      // No moving obstacles, no other robot of this subproblem.
      const SolveResult r = searchPairAlone(*problem_, space_.robot(a), space_.robot(b), options_.pair_proof_expansions,
                                            problem_->deadline.within(problem_->deadline.remaining() / 8));
      stats_->low_level_expansions += r.stats.low_level_expansions;
      if (r.status != SolveStatus::Infeasible) continue;
      proof_culprits_ = {space_.robot(a), space_.robot(b)};
      proof_ = space_.label(a) + " and " + space_.label(b) +
               " cannot both reach their targets around the obstacles they must avoid, even " +
               "with no other robot moving (" + r.reason + ")";
    }
  }
}

// Replaces agent a's path in the table and its edges in the collision graph (`partners`:
// the agents the new path collides with).
void LnsSearch::replacePath(int a, const StatePath& path, const std::vector<int>& partners) {
  ++kept_;
  table_.remove(a);
  table_.insert(a, path);
  for (int b : partners_[a])
    partners_[b].erase(std::lower_bound(partners_[b].begin(), partners_[b].end(), a));
  partners_[a].clear();
  for (int b : partners) link(a, b);
}

void LnsSearch::link(int a, int b) {
  auto add = [](std::vector<int>& v, int x) {
    const auto it = std::lower_bound(v.begin(), v.end(), x);
    if (it == v.end() || *it != x) v.insert(it, x);
  };
  add(partners_[a], b);
  add(partners_[b], a);
}

int LnsSearch::collidingPairs() const {
  std::size_t ends = 0;
  for (const auto& p : partners_) ends += p.size();
  return static_cast<int>(ends / 2);
}

// Local repairs (path_splice.h): with splice_each_colliding, in a subproblem of more than twice
// a neighbourhood's robots, one of each colliding agent in a random order, each kept only if
// the agent then meets fewer agents (the windows are tried until one does); else one of a
// random colliding agent, kept unless it meets more. A robot parked where a late robot passes,
// or one whose rest of the way a delay pushes into others, is mostly repaired in a few hundred
// expansions, where a repair that replans it whole around hundreds of long paths runs out of
// its searches' expansions.
void LnsSearch::splices() {
  std::vector<int> colliding;
  for (int a = 0; a < n_; ++a) {
    if (!partners_[a].empty()) colliding.push_back(a);
  }
  if (colliding.empty()) return;
  // In a subproblem of at most twice a neighbourhood's robots a repair replans much of it, and
  // the local repairs that fail (their windows' searches spent in full) would take the time of
  // the joint repairs that untie its knots.
  if (!options_.splice_each_colliding || n_ <= 2 * options_.neighborhood_size) {
    splice(pick(colliding), /*fewer=*/false);
    return;
  }
  shuffle(colliding);
  for (int a : colliding) {
    if (outOfBudget()) return;
    // An earlier splice of this pass may have repaired it. One that failed is not tried again
    // until some path is kept: with the same table it mostly fails again, and a failing local
    // repair spends its windows' searches in full.
    if (partners_[a].empty() || splice_failed_at_[a] == kept_) continue;
    if (!splice(a, /*fewer=*/true)) splice_failed_at_[a] = kept_;
  }
}

bool LnsSearch::splice(int a, bool fewer) {
  const std::vector<int> starts = collisionStarts(space_, a, table_);
  if (starts.empty()) return false;
  const std::size_t had = partners_[a].size();
  std::vector<int> partners;
  const auto meets = [&](const StatePath& path) {
    partners = table_.partners(a, path);
    return partners.size() < had;
  };
  const SpliceResult r =
      spliceAround(space_, a, table_, pick(starts), /*delays=*/true, problem_->deadline,
                   options_.max_expansions_per_search, fewer ? meets : std::function<bool(const StatePath&)>{});
  stats_->low_level_expansions += r.expansions;
  if (!r.path) return false;
  if (!fewer) partners = table_.partners(a, *r.path);
  if (partners.size() > had) return false;
  replacePath(a, *r.path, partners);
  return true;
}

void LnsSearch::repair() {
  ++stats_->high_level_nodes;
  if (options_.splice) {
    splices();
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
  if (method == kJoint) {
    joint_before_.assign(n_, StatePath{});
    for (std::size_t i = 0; i < group.size(); ++i) joint_before_[group[i]] = old[i];
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
    ++kept_;
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

}  // namespace fleet_planner
