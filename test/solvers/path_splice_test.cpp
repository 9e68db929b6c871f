// Local repairs of LA-LNS (path_splice.h) and the safe interval search's pieces between two
// states of a path: on crossing robots of every footprint kind, a repaired path keeps its start
// and target, moves only along its graph's actions, collides with nobody wherever it differs
// from the old one, and (without delays) meets no agent the old path did not; a window whose
// path the caller rejects gives way to the next one.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

#include "fleet_planner/runtime/random.h"
#include "fleet_planner/solvers/lns/path_splice.h"
#include "fleet_planner/solvers/search/safe_interval_search.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "pocket_corridor.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

// Robots of every footprint kind whose shortest ways cross in the middle of a 14 x 14 map.
std::vector<Robot> crossingRobots() {
  return {dot("d", {1, 7, 0}, {12, 7, 0}), bar("b", {7, 1, 2}, {7, 12, 2}),
          triangle("p", {12, 5, 1}, {1, 5, 1}),
          makeRobot("c", Footprint::circle(0.9), {5, 12, 3}, {5, 2, 3}),
          bar("e", {2, 10, 0}, {11, 3, 3})};
}

// Agent a can do the motion from s to n in one step.
bool isStep(const SearchSpace& space, int a, StateId s, StateId n) {
  if (s == n) return true;
  bool found = false;
  space.graph(a).forEachSuccessor(s, [&](Action act, StateId next) {
    found = found || (next == n && space.allows(a, s, act));
  });
  return found;
}

// Agent a doing `path`'s motion of step t collides with someone in the table.
bool collidesAt(const SearchSpace& space, int a, const SoftPathTable& table, const StatePath& path,
                int t) {
  const StateId s = stateAt(path, t), n = stateAt(path, t + 1);
  std::vector<int> met;
  table.collisions(a, s, stepAction(space.graph(a), s, n), t, met);
  return !met.empty();
}

TEST(PathSplice, RepairedPathsKeepTheirEndsAndAvoidEveryoneWhereTheyChanged) {
  const World w(freeMap(14, 14), crossingRobots());
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  Rng rng(11);
  int repaired[3] = {0, 0, 0};
  int made_up = 0;      // delayed repairs back on the old timing at the end
  int wider_kept = 0;   // repairs whose first window `keep` rejected and a later one passed
  for (int round = 0; round < 60; ++round) {
    // Shortest paths with random waits (before them and on the way), so that they cross at
    // other times and a delay can be made up.
    SoftPathTable table(space);
    for (int a = 0; a < space.numAgents(); ++a) {
      const LowLevelResult r = spaceTimeAStar(space, a, AgentConstraints{}, Deadline::in(5.0));
      ASSERT_EQ(r.outcome, LowLevelResult::Outcome::Found);
      StatePath path(static_cast<std::size_t>(rng.uniformInt(0, 4)), space.start(a));
      for (StateId s : r.path) {
        const int copies = rng.uniformInt(0, 3) == 0 ? 2 : 1;
        path.insert(path.end(), static_cast<std::size_t>(copies), s);
      }
      table.insert(a, path);
    }
    for (int a = 0; a < space.numAgents(); ++a) {
      const StatePath old = table.path(a);
      const std::vector<int> before = table.partners(a);
      for (int t : collisionStarts(space, a, table)) {
        ASSERT_TRUE(collidesAt(space, a, table, old, t)) << "round " << round << ", step " << t;
        // On time; with delays; with delays and only paths that meet fewer agents kept.
        const auto fewer = [&](const StatePath& p) { return table.partners(a, p).size() < before.size(); };
        std::optional<StatePath> first_window;
        for (int mode : {0, 1, 2}) {
          const bool delays = mode > 0;
          const SpliceResult r =
              mode < 2 ? spliceAround(space, a, table, t, delays, Deadline::in(5.0), 100000)
                       : spliceAround(space, a, table, t, delays, Deadline::in(5.0), 100000, fewer);
          if (mode == 1) first_window = r.path;
          if (!r.path) continue;
          ++repaired[mode];
          const StatePath& path = *r.path;
          if (mode == 2) {
            ASSERT_TRUE(fewer(path)) << "round " << round << ": a path `keep` rejects was returned";
            if (first_window && !fewer(*first_window)) ++wider_kept;
          }
          ASSERT_EQ(path.front(), old.front());
          ASSERT_EQ(path.back(), space.target(a));
          for (std::size_t k = 0; k + 1 < path.size(); ++k)
            ASSERT_TRUE(isStep(space, a, path[k], path[k + 1])) << "round " << round << ", step " << k;
          EXPECT_FALSE(collidesAt(space, a, table, path, t)) << "round " << round << ", step " << t;
          const int until = static_cast<int>(std::max(path.size(), old.size()));
          int changed = 0;
          for (int k = 0; k <= until; ++k) {
            if (stateAt(path, k) == stateAt(old, k) && stateAt(path, k + 1) == stateAt(old, k + 1)) continue;
            if (!delays || k < t) {  // a delayed rest of the way may meet others
              ASSERT_FALSE(collidesAt(space, a, table, path, k)) << "round " << round << ", step " << k;
            }
            ++changed;
          }
          EXPECT_GT(changed, 0);
          if (r.rejoin >= 0) {
            // The rest of the old path, r.delay steps later, less at most r.delay of its waits.
            std::size_t i = static_cast<std::size_t>(r.rejoin + r.delay), j = static_cast<std::size_t>(r.rejoin);
            int skipped = 0;
            while (j < old.size()) {
              if (i < path.size() && path[i] == old[j]) {
                ++i;
                ++j;
              } else {
                ASSERT_TRUE(old[j] == old[j - 1] && skipped < r.delay)
                    << "round " << round << ": the rest of the path leaves the old one at step " << j;
                ++skipped;
                ++j;
              }
            }
            ASSERT_EQ(i, path.size()) << "round " << round;
          }
          if (!delays) {
            EXPECT_EQ(r.delay, 0);
          }
          if (r.delay > 0 && path.size() == old.size()) ++made_up;
          if (!delays) {
            const std::vector<int> after = table.partners(a, path);
            EXPECT_TRUE(std::includes(before.begin(), before.end(), after.begin(), after.end()))
                << "round " << round << ": a repair without delays met a new agent";
          }
        }
      }
    }
  }
  EXPECT_GT(repaired[0], 20) << "enough collisions should be repairable on time";
  EXPECT_GT(repaired[1], 20) << "enough collisions should be repairable with delays";
  EXPECT_GT(made_up, 0) << "some delays should be made up by the paths' own waits";
  EXPECT_GT(repaired[2], 10) << "enough collisions should be repairable meeting fewer agents";
  EXPECT_GT(wider_kept, 0) << "a window `keep` rejects should give way to a later one";
}

// The piece's own steps (all but the state it holds from its last step on) collide with nobody.
bool pieceIsFree(const SearchSpace& space, int a, const SoftPathTable& table, const StatePath& piece) {
  for (int k = 0; k + 1 < static_cast<int>(piece.size()); ++k) {
    if (collidesAt(space, a, table, piece, k)) return false;
  }
  return true;
}

// A piece from a state at one step to a state at a later step: held until then when reached
// early, or reached later by up to max_delay steps.
TEST(SafeIntervalSegment, ReachesItsEndStateOnTimeOrWithinTheDelay) {
  // The runner drives east through the corridor while the walker drives west from x = 9 to
  // x = 3 (6 steps alone): it must let the runner pass in the pocket, turn round there and come
  // out, so it reaches x = 3 at step 12.
  PocketCorridor c(dot("walker", {9, 0, 1}, {3, 0, 1}));
  const SearchSpace& space = c.space;
  const SoftPathTable& table = c.table;
  ASSERT_FALSE(c.runner.empty());
  const StateId from = space.start(1), to = space.target(1);
  auto segment = [&](int t1, int max_delay) {
    return safeIntervalSegment(space, 1, table, from, 0, to, t1, max_delay, Deadline::in(5.0), 100000);
  };
  // Due at step 30: reached early and held until then.
  const SafeIntervalResult on_time = segment(30, 0);
  ASSERT_EQ(on_time.outcome, SafeIntervalResult::Outcome::Found);
  ASSERT_EQ(on_time.path.size(), 31u);
  EXPECT_EQ(on_time.path.front(), from);
  EXPECT_EQ(on_time.path.back(), to);
  EXPECT_TRUE(pieceIsFree(space, 1, table, on_time.path));
  bool in_pocket = false;
  for (StateId s : on_time.path) in_pocket = in_pocket || space.graph(1).pose(s).y == 1;
  EXPECT_TRUE(in_pocket);
  // Due at step 8: too soon, unless it may come 4 steps late.
  EXPECT_NE(segment(8, 0).outcome, SafeIntervalResult::Outcome::Found);
  EXPECT_NE(segment(8, 3).outcome, SafeIntervalResult::Outcome::Found);
  const SafeIntervalResult late = segment(8, 20);
  ASSERT_EQ(late.outcome, SafeIntervalResult::Outcome::Found);
  EXPECT_EQ(late.path.size(), 13u) << "earliest arrival: step 12";
  EXPECT_EQ(late.path.back(), to);
  EXPECT_TRUE(pieceIsFree(space, 1, table, late.path));
  // x = 7 is on the runner's way at steps 6-7: reaching it at step 2 and standing there until
  // step 10 collides, and coming back to it from the pocket takes longer.
  const StateId on_way = space.graph(1).id({7, 0, 1});
  EXPECT_NE(safeIntervalSegment(space, 1, table, from, 0, on_way, 10, 0, Deadline::in(5.0), 100000).outcome,
            SafeIntervalResult::Outcome::Found);
}

}  // namespace
}  // namespace fleet_planner::test
