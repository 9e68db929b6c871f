// LA-LNS: which agents a repair replans; see lns_search.h.
#include <algorithm>
#include <numeric>

#include "fleet_planner/solvers/search/space_time_astar.h"
#include "lns_search.h"

namespace fleet_planner {

int LnsSearch::pick(const std::vector<int>& from) {
  return from[rng_.uniformInt(0, static_cast<std::int64_t>(from.size()) - 1)];
}

void LnsSearch::shuffle(std::vector<int>& v) {
  for (std::size_t i = v.size(); i > 1; --i)
    std::swap(v[i - 1], v[rng_.uniformInt(0, static_cast<std::int64_t>(i) - 1)]);
}

Method LnsSearch::chooseMethod() {
  if (n_ <= options_.joint_robots) return kJoint;
  double total = 0;
  for (double w : weights_) total += w;
  double r = rng_.uniform01() * total;
  for (int m = 0; m < kMethods; ++m) {
    if ((r -= weights_[m]) < 0) return static_cast<Method>(m);
  }
  return kRandom;
}

std::vector<int> LnsSearch::neighborhood(Method method) {
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

// A colliding agent and up to joint_size - 1 of its partners.
std::vector<int> LnsSearch::knot() {
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

// Shortest path of a around hard obstacles only (empty if none or out of time); cached.
const StatePath& LnsSearch::idealPath(int a) {
  if (ideal_[a].empty() && !ideal_absent_[a]) {
    const LowLevelResult r = spaceTimeAStar(space_, a, AgentConstraints{}, problem_->deadline);
    stats_->low_level_expansions += r.expansions;
    if (r.outcome == LowLevelResult::Outcome::Found) ideal_[a] = r.path;
    ideal_absent_[a] = r.outcome == LowLevelResult::Outcome::NoPath;
  }
  return ideal_[a];
}

}  // namespace fleet_planner
