// The robots a parking plan left, planned together once everybody else has stopped; see end_game.h.
#include "fleet_planner/solvers/lns/end_game.h"

#include <algorithm>
#include <deque>

#include "fleet_planner/solvers/lns/la_lns.h"
#include "fleet_planner/solvers/lns/pocket_repair.h"

namespace fleet_planner {

namespace {

// Agent a's shortest way home from s among the static obstacles (down its distance table).
StatePath wayHome(const SearchSpace& space, int a, StateId s) {
  StatePath way{s};
  const StateGraph& g = space.graph(a);
  while (space.distance(a, s) > 0) {
    StateId best = kNoState;
    g.forEachSuccessor(s, [&](Action act, StateId next) {
      if (best == kNoState && space.allows(a, s, act) && space.distance(a, next) == space.distance(a, s) - 1)
        best = next;
    });
    if (best == kNoState) break;
    way.push_back(s = best);
  }
  return way;
}

// Cells marked in `way` grown by `by` cells (4-neighbourhood).
void grow(std::vector<char>& way, int width, int height, int by) {
  std::deque<std::pair<int, int>> open;  // (cell, depth)
  for (int i = 0; i < width * height; ++i) {
    if (way[i]) open.push_back({i, 0});
  }
  while (!open.empty()) {
    const auto [c, d] = open.front();
    open.pop_front();
    if (d == by) continue;
    const int x = c % width, y = c / width;
    const int next[4][2] = {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}};
    for (const auto& n : next) {
      if (n[0] < 0 || n[1] < 0 || n[0] >= width || n[1] >= height) continue;
      const int k = n[1] * width + n[0];
      if (way[k]) continue;
      way[k] = 1;
      open.push_back({k, d + 1});
    }
  }
}

}  // namespace

std::optional<std::vector<StatePath>> endGame(const SearchSpace& space, const Subproblem& problem,
                                              const std::vector<StatePath>& paths,
                                              const std::vector<char>& home,
                                              const LaLnsOptions& lns, const Deadline& deadline,
                                              const EndGameOptions& options, long long& expansions) {
  const int n = space.numAgents();
  if (!problem.returning.empty() || n == 0) return std::nullopt;
  // The step from which nobody of the plan nor of other subproblems moves again.
  int settled = space.reservations().lastChange() + 1;
  for (const StatePath& p : paths) settled = std::max(settled, static_cast<int>(p.size()) - 1);

  std::vector<char> in(n, 0), way;
  std::vector<int> group;
  for (int a = 0; a < n; ++a) {
    if (home[a]) continue;
    in[a] = 1;
    group.push_back(a);
    markWay(space, a, wayHome(space, a, paths[a].back()), way);
  }
  if (group.empty()) return std::nullopt;
  const StateGraph& g0 = space.graph(0);
  const int step = std::max(1, g0.actionModel().step);
  Instance instance = *problem.instance;
  for (int round = 0; round < options.rounds && !deadline.expired(); ++round) {
    if (round > 0) grow(way, g0.width(), g0.height(), (options.margin * step) << (round - 1));
    for (int b = 0; b < n; ++b) {
      if (!in[b] && !clearOfWay(space, b, paths[b].back(), way)) {
        in[b] = 1;
        group.push_back(b);
      }
    }
    if (static_cast<int>(group.size()) > options.max_group) return std::nullopt;
    Subproblem sub;
    sub.instance = &instance;
    sub.graphs = problem.graphs;
    sub.blocked = problem.blocked;
    sub.seed = problem.seed;
    // The caller's expansion budget holds for the group too (outcomes that do not depend on the
    // machine's speed).
    if (problem.max_expansions >= 0) sub.max_expansions = std::max(0LL, problem.max_expansions - expansions);
    for (const MovingObstacle& m : problem.moving) {
      if (!m.path.empty()) sub.blocked.push_back({m.robot, m.path.back()});
    }
    for (int a = 0; a < n; ++a) {
      const int r = space.robot(a);
      const GridPose stands = space.graph(a).pose(paths[a].back());
      if (!in[a]) {
        sub.blocked.push_back({r, stands});
        continue;
      }
      Robot& robot = instance.robots[r];
      robot.start = stands;
      robot.start_yaw.reset();
      robot.start_turn = 0;
      robot.conflicts_from = 0;
      sub.robots.push_back(r);
    }
    // Each round gets an equal share of what is left.
    sub.deadline = deadline.within(deadline.remaining() / (options.rounds - round));
    LaLnsOptions inner = lns;
    inner.end_game = false;
    const SolveResult solved = LaLns(inner).solve(sub);
    expansions += solved.stats.low_level_expansions;
    if (!solved.success()) continue;
    std::vector<StatePath> out = paths;
    std::size_t k = 0;
    for (int a = 0; a < n; ++a) {
      if (!in[a]) continue;
      StatePath& p = out[a];
      p.resize(static_cast<std::size_t>(settled) + 1, p.back());
      const Path& tail = solved.paths[k++];
      for (std::size_t i = 1; i < tail.size(); ++i) p.push_back(space.graph(a).id(tail[i]));
    }
    if (firstConflict(space, out)) return std::nullopt;  // a defect: the parts are collision-free
    return out;
  }
  return std::nullopt;
}

}  // namespace fleet_planner
