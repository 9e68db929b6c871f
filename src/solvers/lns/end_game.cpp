// The robots a parking plan left, planned together once everybody else has stopped; see end_game.h.
#include "fleet_planner/solvers/lns/end_game.h"

#include <algorithm>
#include <deque>
#include <queue>

#include "fleet_planner/solvers/lns/la_lns.h"
#include "fleet_planner/solvers/lns/parking_plan.h"
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

// Agent a's way home from s among the static obstacles through fewest robots standing where
// their paths end (`standing`: their cells): a state whose body meets one costs the parking
// plan's crowd_cost steps more, as the parking plan's ways to clear do. Its shortest way home
// leads through robots parked along a street that another way passes by; the robots on the way
// chosen here are the ones the end game must move. Empty if there is none.
StatePath wayHomeAround(const SearchSpace& space, int a, StateId from, const std::vector<char>& standing) {
  const int crowd_cost = ParkingPlanOptions{}.crowd_cost;
  const StateGraph& g = space.graph(a);
  const std::size_t states = static_cast<std::size_t>(g.stateIdCount());
  std::vector<int> cost(states, -1);
  std::vector<StateId> parent(states, kNoState);
  using Entry = std::pair<long long, StateId>;  // (f, state)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  cost[from] = 0;
  open.push({space.distance(a, from), from});
  while (!open.empty()) {
    const auto [f, s] = open.top();
    open.pop();
    if (f != cost[s] + space.distance(a, s)) continue;
    if (s == space.target(a)) {
      StatePath way;
      for (StateId q = s; q != kNoState; q = parent[q]) way.push_back(q);
      std::reverse(way.begin(), way.end());
      return way;
    }
    g.forEachSuccessor(s, [&](Action act, StateId next) {
      if (space.distance(a, next) < 0 || !space.allows(a, s, act)) return;
      const int c = cost[s] + 1 + (clearOfWay(space, a, next, standing) ? 0 : crowd_cost);
      if (cost[next] >= 0 && cost[next] <= c) return;
      cost[next] = c;
      parent[next] = s;
      open.push({c + space.distance(a, next), next});
    });
  }
  return {};
}

// Each cell's distance (4-neighbourhood, in cells) from the nearest cell marked in `way`, up to
// `limit`; -1 beyond it.
std::vector<int> depthFrom(const std::vector<char>& way, int width, int height, int limit) {
  std::vector<int> depth(way.size(), -1);
  std::deque<int> open;
  for (std::size_t i = 0; i < way.size(); ++i) {
    if (way[i]) {
      depth[i] = 0;
      open.push_back(static_cast<int>(i));
    }
  }
  while (!open.empty()) {
    const int c = open.front();
    open.pop_front();
    if (depth[c] == limit) continue;
    const int x = c % width, y = c / width;
    const int next[4][2] = {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}};
    for (const auto& n : next) {
      if (n[0] < 0 || n[1] < 0 || n[0] >= width || n[1] >= height) continue;
      const int k = n[1] * width + n[0];
      if (depth[k] >= 0) continue;
      depth[k] = depth[c] + 1;
      open.push_back(k);
    }
  }
  return depth;
}

// The least depth of agent b's body at state s (-1: none within the map's depths).
int depthOf(const SearchSpace& space, int b, StateId s, const std::vector<int>& depth) {
  const StateGraph& g = space.graph(b);
  const GridPose p = g.pose(s);
  int least = -1;
  forEachMapCell(space.cells(b).body(p.heading), {p.x, p.y}, g.width(), g.height(), [&](std::size_t cell) {
    if (depth[cell] >= 0 && (least < 0 || depth[cell] < least)) least = depth[cell];
    return true;
  });
  return least;
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

  const StateGraph& g0 = space.graph(0);
  std::vector<char> in(n, 0), way, standing(static_cast<std::size_t>(g0.width()) * g0.height(), 0);
  std::vector<int> group;
  for (int a = 0; a < n; ++a) {
    if (home[a]) markWay(space, a, {paths[a].back()}, standing);
  }
  for (int a = 0; a < n; ++a) {
    if (home[a]) continue;
    in[a] = 1;
    group.push_back(a);
    const StatePath around = wayHomeAround(space, a, paths[a].back(), standing);
    markWay(space, a, around.empty() ? wayHome(space, a, paths[a].back()) : around, way);
  }
  if (group.empty()) return std::nullopt;
  const int step = std::max(1, g0.actionModel().step);
  Instance instance = *problem.instance;
  // The robots standing near the ways, by their distance from them (ties: index).
  const int reach = options.margin * step * ((1 << std::max(0, options.rounds - 1)) - 1);
  const std::vector<int> depth = depthFrom(way, g0.width(), g0.height(), reach);
  std::vector<std::pair<int, int>> near;  // (depth, agent)
  for (int b = 0; b < n; ++b) {
    const int d = in[b] ? -1 : depthOf(space, b, paths[b].back(), depth);
    if (d >= 0) near.push_back({d, b});
  }
  std::sort(near.begin(), near.end());
  std::size_t taken = 0;
  std::size_t last_group = 0;  // robots of the last round planned (0: none yet)
  for (int round = 0; round < options.rounds && !deadline.expired(); ++round) {
    // Round r takes the robots within margin x (2^r - 1) cells of the ways; in a crowd, the
    // nearest of them up to max_group.
    const int within = options.margin * step * ((1 << round) - 1);
    while (taken < near.size() && near[taken].first <= within &&
           (round == 0 || static_cast<int>(group.size()) < options.max_group)) {
      in[near[taken].second] = 1;
      group.push_back(near[taken++].second);
    }
    if (static_cast<int>(group.size()) > options.max_group) return std::nullopt;
    // A round that adds nobody would plan the group of the round before again, with the same
    // seed and about as much time: it would fail the same way. Its time is left to the rounds
    // after it, or to the repairs after the end game.
    if (group.size() == last_group) continue;
    last_group = group.size();
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
