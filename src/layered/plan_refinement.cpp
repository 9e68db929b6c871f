// Plan refinement; see plan_refinement.h.
#include "fleet_planner/layered/plan_refinement.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/solvers/search/agent_constraints.h"
#include "fleet_planner/solvers/search/safe_interval_search.h"
#include "fleet_planner/solvers/search/search_space.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "path_steps.h"

namespace fleet_planner {

namespace {

using path_steps::radiusOf;

// The robot's cheapest path with nobody else around.
Path idealPath(const Instance& instance, const FleetGraphs& graphs, int robot, const Deadline& deadline) {
  Subproblem sub;
  sub.instance = &instance;
  sub.graphs = &graphs;
  sub.robots = {robot};
  const SearchSpace space(sub);
  if (space.stopped() || !space.problem().empty()) return {};  // stopped: the deadline passed
  const LowLevelResult found = spaceTimeAStar(space, 0, AgentConstraints{}, deadline);
  Path path;
  for (StateId s : found.path) path.push_back(space.graph(0).pose(s));
  return path;
}

// Up to `count` robots whose paths stand in the way of robot i's ideal path: most states whose
// footprint overlaps a footprint of the ideal path first (ties: index).
std::vector<int> blockers(const FleetGraphs& graphs, const std::vector<Path>& paths, int i, const Path& ideal,
                          int count) {
  std::vector<std::pair<int, int>> scored;  // (-score, robot)
  const FootprintCells& A = graphs.cells(i);
  for (int j = 0; j < static_cast<int>(paths.size()); ++j) {
    if (j == i) continue;
    const FootprintCells& B = graphs.cells(j);
    const int reach = radiusOf(A) + radiusOf(B);
    int score = 0;
    for (const GridPose& q : paths[j]) {
      for (const GridPose& p : ideal) {
        if (fartherApart(p, q, reach)) continue;
        if (footprintsOverlap(A, p, B, q)) {
          ++score;
          break;
        }
      }
    }
    if (score > 0) scored.push_back({-score, j});
  }
  std::sort(scored.begin(), scored.end());
  std::vector<int> out;
  for (std::size_t k = 0; k < scored.size() && static_cast<int>(k) < count; ++k) out.push_back(scored[k].second);
  return out;
}

// One refinement: the plan being improved, the bounds learnt so far, and the passes.
class Refiner {
 public:
  Refiner(const Instance& instance, const FleetGraphs& graphs, std::vector<Path>& paths, const Deadline& deadline,
          const RefinementOptions& options)
      : instance_(instance), graphs_(graphs), paths_(paths), deadline_(deadline), options_(options),
        n_(static_cast<int>(paths.size())),
        max_expansions_(std::min(options.max_expansions, options.expansions_per_robot * n_)),
        lower_(n_, 0), distance_(n_, -1), ideal_(n_),
        single_failed_at_(n_, -1), group_failed_at_(n_, -1) {
    // Every robot's path in one soft path table, kept up to date as paths are replaced: a
    // search reads the others' paths from it (its own is ignored), and only the searched
    // robot's distance table is built, for the search.
    Subproblem all;
    all.instance = &instance;
    all.graphs = &graphs;
    all.robots.resize(n_);
    std::iota(all.robots.begin(), all.robots.end(), 0);
    all.deadline = deadline;
    space_ = std::make_unique<SearchSpace>(all, false);
    if (!space_->problem().empty()) return;
    table_ = std::make_unique<SoftPathTable>(*space_);
    for (int i = 0; i < n_; ++i) {
      if (!track(i)) return;
    }
    tracked_ = true;
    for (int i = 0; i < n_; ++i) bound(i);
  }

  RefinementStats run() {
    const auto start = std::chrono::steady_clock::now();
    while (tracked_ && stats_.passes < options_.max_passes && !outOfTime() && stats_.expansions < max_expansions_) {
      ++stats_.passes;
      const int improved = singlePass();
      stats_.improved += improved;
      if (improved > 0) continue;
      if (options_.group_size < 2) break;
      const int grouped = groupPass();
      stats_.improved += grouped;
      if (grouped == 0) break;
    }
    stats_.deadline_hit = outOfTime();
    stats_.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats_;
  }

 private:
  int costOf(int i) const { return pathCost(paths_[i], instance_.robots[i].target); }
  int makespan() const {
    int m = 0;
    for (int i = 0; i < n_; ++i) m = std::max(m, costOf(i));
    return m;
  }
  // A search is started only if the longest one so far would still end before the deadline:
  // on hundreds of long paths, building one search's reservation table takes most of a second.
  bool outOfTime() const { return deadline_.expired() || deadline_.remaining() < longest_search_s_; }
  bool outOfBudget() const { return outOfTime() || stats_.expansions >= max_expansions_; }
  template <typename Search>
  auto timed(Search&& search) {
    const auto t = std::chrono::steady_clock::now();
    auto result = search();
    longest_search_s_ =
        std::max(longest_search_s_, std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count());
    return result;
  }
  // Robots by how much they are delayed beyond their lower bound, most first.
  std::vector<int> delayOrder() const {
    std::vector<int> order(n_);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return costOf(a) - lower_[a] > costOf(b) - lower_[b]; });
    return order;
  }

  // Each robot replanned alone around the others, kept when cheaper.
  int singlePass() {
    int improved = 0;
    for (int i : delayOrder()) {
      if (outOfBudget()) break;
      const int cost = costOf(i);
      if (cost <= bound(i)) continue;
      if (single_failed_at_[i] == changes_) continue;  // the same search again: it fails again
      ++stats_.searches;
      Path better = timed([&] { return cheaperPath(i, cost); });
      const int new_cost = better.empty() ? -1 : pathCost(better, instance_.robots[i].target);
      if (new_cost < 0 || new_cost >= cost) {
        if (!deadline_.expired()) single_failed_at_[i] = changes_;
        continue;
      }
      stats_.soc_saved += cost - new_cost;
      paths_[i] = std::move(better);
      if (!track(i)) return improved + 1;
      ++improved;
    }
    return improved;
  }

  // Robot i and those in the way of its ideal path, replanned in turn around the rest: i
  // first, then the others by how much they stand in its way; kept when their sum of costs
  // drops and none of them ends after the makespan.
  int groupPass() {
    int improved = 0;
    for (int i : delayOrder()) {
      if (outOfBudget()) break;
      // The group's robots move too: only i's distance bounds its cost.
      if (distance_[i] < 0 || costOf(i) <= distance_[i]) continue;
      if (group_failed_at_[i] == changes_) continue;  // the same group, the same searches
      if (ideal_[i].empty()) ideal_[i] = idealPath(instance_, graphs_, i, deadline_);
      std::vector<int> order = blockers(graphs_, paths_, i, ideal_[i], options_.group_size - 1);
      if (order.empty()) continue;
      order.insert(order.begin(), i);
      ++stats_.group_searches;
      if (timed([&] { return replanInTurn(order); })) {
        ++improved;
      } else if (!deadline_.expired()) {
        group_failed_at_[i] = changes_;
      }
    }
    return improved;
  }

  // Prioritized planning of the group (`order`, first planned first): all of it out of the
  // table, then each robot searched around the rest and the members planned before it (the
  // later members do not exist for it). Each search only looks for arrivals that can still
  // make the group cheaper (and by the makespan); on any failure the old paths go back.
  bool replanInTurn(const std::vector<int>& order) {
    const std::size_t n = order.size();
    const int limit = makespan();
    long long before = 0;
    std::vector<StatePath> old(n);
    for (std::size_t k = 0; k < n; ++k) {
      before += costOf(order[k]);
      old[k] = table_->path(order[k]);
      table_->remove(order[k]);
    }
    std::vector<Path> fresh(n);
    long long after = 0;
    bool planned = true;
    for (std::size_t k = 0; k < n && planned; ++k) {
      const int r = order[k];
      long long later = 0;  // the least the members after r can cost
      for (std::size_t m = k + 1; m < n; ++m) later += std::max(0, distance_[order[m]]);
      const long long cap = std::min<long long>(limit, before - 1 - after - later);
      planned = cap >= 0 && !outOfBudget() && space_->buildDistances(r, deadline_);
      if (!planned) break;
      distance_[r] = space_->distance(r, space_->start(r));
      const SafeIntervalResult found = safeIntervalSearch(*space_, r, *table_, deadline_, options_.max_nodes_per_search,
                                                          static_cast<int>(cap));
      space_->dropDistances(r);
      stats_.expansions += found.expansions;
      planned = found.outcome == SafeIntervalResult::Outcome::Found;
      if (!planned) break;
      table_->insert(r, found.path);
      for (StateId st : found.path) fresh[k].push_back(space_->graph(r).pose(st));
      after += pathCost(fresh[k], instance_.robots[r].target);
    }
    if (planned && after < before) {
      for (std::size_t k = 0; k < n; ++k) paths_[order[k]] = std::move(fresh[k]);
      stats_.soc_saved += before - after;
      changes_ += static_cast<long long>(n);
      return true;
    }
    for (std::size_t k = 0; k < n; ++k) {
      if (table_->contains(order[k])) table_->remove(order[k]);
      table_->insert(order[k], old[k]);
    }
    return false;
  }

  // Robot i's path (paths_[i]) put in the table in place of its old one; false (and the
  // refinement ends) if it is not a path of i's state graph.
  bool track(int i) {
    const StateGraph& g = space_->graph(i);
    StatePath states;
    for (const GridPose& p : paths_[i]) {
      const StateId s = g.id(p);
      if (s == kNoState) return tracked_ = false;
      if (!states.empty() && s != states.back()) {
        bool edge = false;
        g.forEachSuccessor(states.back(), [&](Action, StateId next) { edge = edge || next == s; });
        if (!edge) return tracked_ = false;
      }
      states.push_back(s);
    }
    if (states.empty()) return tracked_ = false;
    if (table_->contains(i)) table_->remove(i);
    table_->insert(i, states);
    ++changes_;
    return true;
  }

  // Robot i's lower bound, kept in lower_: its distance (once known) and the earliest arrival
  // at its target for good that the others' passes over it allow (it changes as their paths
  // are replaced). A robot held up by a late pass over its target is searched last, if at all.
  int bound(int i) {
    lower_[i] = std::max(distance_[i], earliestArrivalForGood(*space_, i, *table_));
    return lower_[i];
  }

  // Robot i's path around every other robot's path, strictly cheaper than `cost`; empty if
  // there is none (or the search hit a limit). Learns i's lower bound.
  Path cheaperPath(int i, int cost) {
    Path path;
    if (!space_->buildDistances(i, deadline_)) return path;  // the deadline passed
    distance_[i] = space_->distance(i, space_->start(i));
    bound(i);
    // Safe intervals: a wait is one node, so a path that waits for others to pass costs a few
    // expansions, and the bound (arrive before `cost`) ends the search soon when there is no
    // cheaper path, where space-time A* must still try every step of every wait. Any cheaper
    // path improves the plan: a weighted heuristic finds one in fewer expansions than proving
    // the cheapest, and the bound (on the unweighted one) still keeps only cheaper paths.
    if (distance_[i] >= 0 && lower_[i] < cost) {
      // Its own path out of the table while it searches: the table's answers leave it out
      // anyway, and read the cells' kept steps only for a robot that is not in it.
      const StatePath own = table_->contains(i) ? table_->path(i) : StatePath{};
      if (!own.empty()) table_->remove(i);
      const SafeIntervalResult found = safeIntervalSearch(*space_, i, *table_, deadline_, options_.max_nodes_per_search,
                                                          cost - 1, options_.heuristic_weight);
      if (!own.empty()) table_->insert(i, own);
      stats_.expansions += found.expansions;
      if (found.outcome == SafeIntervalResult::Outcome::Found) {
        for (StateId s : found.path) path.push_back(space_->graph(i).pose(s));
      }
    }
    space_->dropDistances(i);
    return path;
  }

  const Instance& instance_;
  const FleetGraphs& graphs_;
  std::vector<Path>& paths_;
  const Deadline& deadline_;
  const RefinementOptions& options_;
  const int n_;
  const long long max_expansions_;
  RefinementStats stats_;
  std::vector<int> lower_;     // lower bounds on each robot's cost (bound)
  std::vector<int> distance_;  // each robot's distance to its target, learnt from its search; -1: not yet
  std::vector<Path> ideal_;
  // A search depends only on the paths (and the deadline), so a robot whose search failed is
  // not searched again until some path has changed: changes_ counts the paths put in the
  // table, *_failed_at_[i] is its value when robot i's single (group) search last failed.
  long long changes_ = 0;
  std::vector<long long> single_failed_at_;
  std::vector<long long> group_failed_at_;
  double longest_search_s_ = 0.0;
  std::unique_ptr<SearchSpace> space_;  // every robot; distance tables only while searched
  std::unique_ptr<SoftPathTable> table_;
  bool tracked_ = false;  // every path is in table_
};

}  // namespace

RefinementStats refinePlan(const Instance& instance, const FleetGraphs& graphs, std::vector<Path>& paths,
                           const Deadline& deadline, const RefinementOptions& options) {
  return Refiner(instance, graphs, paths, deadline, options).run();
}

}  // namespace fleet_planner
