// Decomposition of a cluster into levels: paper, Methodology, Algorithms 3 and 4.
//
// Legality is kept explicit: every query of a cluster only lets paths touch SATs of that
// cluster, and a level's robots must avoid the targets of every level placed before it and the
// starts of every level after it.
#include <algorithm>
#include <functional>

#include "dependency_oracle.h"

namespace fleet_planner::detail {

namespace {

int startSat(int robot) { return 2 * robot; }
int targetSat(int robot) { return 2 * robot + 1; }

// Tarjan's strongly connected components of a small directed graph, sources first.
std::vector<std::vector<int>> orderedComponents(const std::vector<int>& nodes, const std::vector<std::vector<int>>& out_edges) {
  const int n = static_cast<int>(out_edges.size());
  std::vector<int> index(n, -1), low(n, 0), stack;
  std::vector<char> on_stack(n, 0);
  std::vector<std::vector<int>> comps;
  int counter = 0;
  std::function<void(int)> visit = [&](int v) {
    index[v] = low[v] = counter++;
    stack.push_back(v);
    on_stack[v] = 1;
    for (int w : out_edges[v]) {
      if (index[w] < 0) {
        visit(w);
        low[v] = std::min(low[v], low[w]);
      } else if (on_stack[w]) {
        low[v] = std::min(low[v], index[w]);
      }
    }
    if (low[v] == index[v]) {
      std::vector<int> comp;
      int w;
      do {
        w = stack.back();
        stack.pop_back();
        on_stack[w] = 0;
        comp.push_back(w);
      } while (w != v);
      std::sort(comp.begin(), comp.end());
      comps.push_back(std::move(comp));
    }
  };
  for (int v : nodes) {
    if (index[v] < 0) visit(v);
  }
  std::reverse(comps.begin(), comps.end());  // Tarjan emits sinks first
  return comps;
}

class LevelSplitter {
 public:
  LevelSplitter(DependencyOracle& oracle, const std::vector<int>& cluster)
      : oracle_(oracle), n_(oracle.robots()), avail_(2 * oracle.robots(), 0) {
    for (int r : cluster) avail_[startSat(r)] = avail_[targetSat(r)] = 1;
  }

  const Mask& avail() const { return avail_; }

  // Algorithm 4: splits l into a major level solved first and a remainder solved after it, both
  // keeping clear of `base` (targets of earlier levels, starts of later ones). Past the
  // deadline, l stays whole (still legal).
  std::pair<std::vector<int>, std::vector<int>> bipartition(const std::vector<int>& l, const Mask& base,
                                                            const Deadline& deadline) {
    if (l.size() <= 1) return {l, {}};
    // Step 1: the unavoidance graph: i -> j when i cannot avoid j's target (i goes first) and
    // j -> i when i cannot avoid j's start (j goes first).
    // Only SATs on i's best path can be unavoidable: that path avoids every other one.
    std::vector<std::vector<int>> out(n_), in(n_);
    for (int i : l) {
      if (deadline.expired()) return {l, {}};
      const auto on_path = oracle_.sats(i, avail_, base);
      for (int j : l) {
        if (i == j) continue;
        auto unavoidable = [&](int sat) {
          if (on_path && !std::binary_search(on_path->begin(), on_path->end(), sat)) return false;
          return !pathAvoiding(i, base, {sat});
        };
        if (unavoidable(targetSat(j))) {
          out[i].push_back(j);
          in[j].push_back(i);
        }
        if (unavoidable(startSat(j))) {
          out[j].push_back(i);
          in[i].push_back(j);
        }
      }
    }
    int top = l.front();
    for (int i : l) {
      if (out[i].size() > out[top].size()) top = i;
    }
    // The major set: the robot that must precede most others, with all that must precede it.
    Mask major(n_, 0), remain(n_, 0);
    for (int i : l) remain[i] = 1;
    std::vector<int> queue{top};
    major[top] = 1;
    remain[top] = 0;
    for (std::size_t h = 0; h < queue.size(); ++h) {
      for (int p : in[queue[h]]) {
        if (!major[p]) {
          major[p] = 1;
          remain[p] = 0;
          queue.push_back(p);
        }
      }
    }
    for (;;) {
      if (deadline.expired()) return {l, {}};
      // Step 2: remainder robots that cannot avoid the major set's targets join it.
      for (bool moved = true; moved;) {
        moved = false;
        for (int i : members(remain)) {
          if (!oracle_.satPathExists(i, avail_, with(base, targetsOf(major)))) {
            move(i, major, remain);
            moved = true;
          }
        }
      }
      // Step 3: major robots that cannot avoid the remainder's starts pull those robots in.
      for (bool moved = true; moved;) {
        moved = false;
        for (int i : members(major)) {
          if (oracle_.satPathExists(i, avail_, with(base, startsOf(remain)))) continue;
          const auto needed = oracle_.sats(i, avail_, base);
          for (int j : members(remain)) {
            // Without a path at all (cannot happen for a legal input), take everything.
            if (!needed || std::binary_search(needed->begin(), needed->end(), startSat(j))) {
              move(j, major, remain);
              moved = true;
            }
          }
        }
      }
      // Step 4: done when both are independent levels.
      if (members(remain).empty()) break;
      bool independent = true;
      for (int i : members(remain)) independent = independent && oracle_.satPathExists(i, avail_, with(base, targetsOf(major)));
      for (int i : members(major)) independent = independent && oracle_.satPathExists(i, avail_, with(base, startsOf(remain)));
      if (independent) break;
    }
    return {members(major), members(remain)};
  }

  Mask targetsOf(const Mask& robots) const { return satMask(robots, 1); }
  Mask startsOf(const Mask& robots) const { return satMask(robots, 0); }
  static Mask with(Mask a, const Mask& b) {
    for (std::size_t k = 0; k < a.size(); ++k) a[k] = a[k] || b[k];
    return a;
  }

 private:
  bool pathAvoiding(int i, const Mask& base, std::initializer_list<int> extra) {
    Mask avoid = base;
    for (int s : extra) avoid[s] = 1;
    return oracle_.satPathExists(i, avail_, avoid);
  }
  Mask satMask(const Mask& robots, int which) const {
    Mask m(2 * n_, 0);
    for (int j = 0; j < n_; ++j) {
      if (robots[j]) m[2 * j + which] = 1;
    }
    return m;
  }
  static std::vector<int> members(const Mask& m) {
    std::vector<int> out;
    for (int i = 0; i < static_cast<int>(m.size()); ++i) {
      if (m[i]) out.push_back(i);
    }
    return out;
  }
  static void move(int i, Mask& to, Mask& from) {
    from[i] = 0;
    to[i] = 1;
  }

  DependencyOracle& oracle_;
  int n_;
  Mask avail_;
};

}  // namespace

std::vector<std::vector<int>> initialLevels(DependencyOracle& oracle, const std::vector<int>& cluster) {
  const int n = oracle.robots();
  LevelSplitter splitter(oracle, cluster);
  // Solving-order graph: j -> i when i's path passes j's start (j first), i -> j when it passes
  // j's target (i first).
  std::vector<std::vector<int>> out(n);
  for (int i : cluster) {
    const auto sats = oracle.sats(i, splitter.avail(), {});
    if (!sats) continue;  // cannot happen inside a legal cluster; i then stays with the others
    for (int s : *sats) {
      const int j = s / 2;
      if (s % 2 == 0) {
        out[j].push_back(i);
      } else {
        out[i].push_back(j);
      }
    }
  }
  return orderedComponents(cluster, out);
}

std::vector<std::vector<int>> bipartitionLevels(DependencyOracle& oracle, const std::vector<int>& cluster,
                                                const std::vector<std::vector<int>>& levels, const Deadline& deadline,
                                                bool peel) {
  const int n = oracle.robots();
  LevelSplitter splitter(oracle, cluster);
  std::vector<std::vector<int>> out;
  Mask earlier(n, 0);  // robots of the levels placed so far
  for (std::size_t k = 0; k < levels.size(); ++k) {
    Mask later(n, 0);
    for (std::size_t m = k + 1; m < levels.size(); ++m) {
      for (int r : levels[m]) later[r] = 1;
    }
    std::vector<int> rest = levels[k];
    std::vector<std::vector<int>> tail;  // peeled to go last, the last one first
    // Peeling (beyond the paper): a robot that can go before all the others of the level, or
    // after all of them, becomes a level of its own. Passes over the level, in order, peel every
    // robot that can go at that moment; they repeat while one peels.
    for (bool peeled = peel; peeled && rest.size() > 1 && !deadline.expired();) {
      peeled = false;
      const std::vector<int> candidates = rest;
      for (int i : candidates) {
        if (rest.size() <= 1 || deadline.expired()) break;
        const Mask others = maskOf(rest, n);
        const Mask base = LevelSplitter::with(splitter.targetsOf(earlier), splitter.startsOf(later));
        // Every other robot of the level must still have its way once i's SAT is avoided too.
        auto othersKeepClearOf = [&](int sat) {
          Mask avoid = base;
          avoid[sat] = 1;
          for (int j : rest) {
            if (j != i && !oracle.satPathExists(j, splitter.avail(), avoid)) return false;
          }
          return true;
        };
        Mask rest_but_i = others;
        rest_but_i[i] = 0;
        if (oracle.satPathExists(i, splitter.avail(), LevelSplitter::with(base, splitter.startsOf(rest_but_i))) &&
            othersKeepClearOf(2 * i + 1)) {
          out.push_back({i});  // first: clear of every start still waiting; the others of its target
          earlier[i] = 1;
        } else if (oracle.satPathExists(i, splitter.avail(), LevelSplitter::with(base, splitter.targetsOf(rest_but_i))) &&
                   othersKeepClearOf(2 * i)) {
          tail.push_back({i});  // last: clear of every target reached before it; the others of its start
          later[i] = 1;
        } else {
          continue;
        }
        rest.erase(std::find(rest.begin(), rest.end(), i));
        peeled = true;
      }
    }
    while (!rest.empty()) {
      if (deadline.expired()) {
        out.push_back(rest);
        break;
      }
      const Mask base = LevelSplitter::with(splitter.targetsOf(earlier), splitter.startsOf(later));
      auto [major, remain] = splitter.bipartition(rest, base, deadline);
      for (int r : major) earlier[r] = 1;
      out.push_back(std::move(major));
      rest = std::move(remain);
    }
    for (auto it = tail.rbegin(); it != tail.rend(); ++it) {
      for (int r : *it) earlier[r] = 1;
      out.push_back(*it);
    }
  }
  return out;
}

}  // namespace fleet_planner::detail
