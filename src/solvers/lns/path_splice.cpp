#include "fleet_planner/solvers/lns/path_splice.h"

#include <algorithm>

#include "fleet_planner/solvers/search/safe_interval_search.h"
#include "fleet_planner/solvers/search/space_time_astar.h"

namespace fleet_planner {

namespace {

// Agent a doing its path's motion during step t collides with someone in the table.
bool collidesAt(const SearchSpace& space, int a, const SoftPathTable& table, int t,
                std::vector<int>& scratch) {
  const StatePath& path = table.path(a);
  const StateId s = stateAt(path, t), n = stateAt(path, t + 1);
  scratch.clear();
  table.collisions(a, s, stepAction(space.graph(a), s, n), t, scratch);
  return !scratch.empty();
}

// Agent a waiting during step t at its path's state of time t collides with nobody.
bool canWait(int a, const SoftPathTable& table, int t, std::vector<int>& scratch) {
  scratch.clear();
  table.collisions(a, stateAt(table.path(a), t), Action::Wait, t, scratch);
  return scratch.empty();
}

}  // namespace

std::vector<int> collisionStarts(const SearchSpace& space, int a, const SoftPathTable& table) {
  std::vector<int> starts, scratch;
  const int until =
      std::max(static_cast<int>(table.path(a).size()) - 1, table.lastMove() + 1);
  bool before = false;
  for (int t = 0; t <= until; ++t) {
    const bool now = collidesAt(space, a, table, t, scratch);
    if (now && !before) starts.push_back(t);
    before = now;
  }
  return starts;
}

SpliceResult spliceAround(const SearchSpace& space, int a, const SoftPathTable& table, int t,
                          bool delays, const Deadline& deadline, long long max_expansions,
                          const std::function<bool(const StatePath&)>& keep) {
  SpliceResult result;
  const StatePath& old = table.path(a);
  const int last = static_cast<int>(old.size()) - 1;  // held from here on
  std::vector<int> scratch;
  int end = t;  // last step of the run
  const int until = std::max(last, table.lastMove() + 1);
  while (end < until && collidesAt(space, a, table, end + 1, scratch)) ++end;
  constexpr int kBack[] = {2, 8, 32, 128};
  constexpr int kAhead[] = {8, 32, 128, 512};
  int tried_t0 = -1, tried_t1 = -1;
  for (int w = 0; w < 4; ++w) {
    // The piece starts where the agent can wait: the search's first node is a safe interval.
    int t0 = std::max(0, t - kBack[w]);
    while (t0 > 0 && !canWait(a, table, t0, scratch)) --t0;
    // A window reaching the path's end ends at the target, held for good.
    int t1 = end + kAhead[w];
    if (t1 >= last) t1 = SoftPathTable::kNever;
    // Near the path's start or end, windows clip to the same one: it failed already.
    if (t1 == SoftPathTable::kNever && t0 == tried_t0 && t1 == tried_t1) continue;
    tried_t0 = t0;
    tried_t1 = t1;
    const SafeIntervalResult r = safeIntervalSegment(space, a, table, stateAt(old, t0), t0,
                                                     stateAt(old, t1 == SoftPathTable::kNever ? last : t1),
                                                     t1, delays ? kAhead[w] : 0, deadline,
                                                     max_expansions);
    result.expansions += r.expansions;
    if (r.outcome == SafeIntervalResult::Outcome::Expired) return result;
    if (r.outcome != SafeIntervalResult::Outcome::Found) continue;
    StatePath spliced(old.begin(), old.begin() + std::min(t0, last + 1));
    while (static_cast<int>(spliced.size()) < t0) spliced.push_back(old.back());
    spliced.insert(spliced.end(), r.path.begin(), r.path.end());
    int rejoin = -1, delay = 0;
    if (t1 != SoftPathTable::kNever) {
      rejoin = t1;
      delay = static_cast<int>(spliced.size()) - 1 - t1;
      // The old path's own waits take up the delay, where it has some: after them the path is
      // back on its old timing.
      int owed = delay;
      for (int k = t1 + 1; k <= last; ++k) {
        if (owed > 0 && old[k] == old[k - 1]) {
          --owed;
          continue;
        }
        spliced.push_back(old[k]);
      }
    }
    if (keep && !keep(spliced)) continue;
    result.rejoin = rejoin;
    result.delay = delay;
    result.path = std::move(spliced);
    return result;
  }
  return result;
}

}  // namespace fleet_planner
