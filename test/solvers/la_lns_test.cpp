// LA-LNS and its two low levels: the soft path table against the backends' conflict code, the
// safe interval search's long waits, and moving obstacles. Every plan goes through the
// independent validator.
#include "fleet_planner/solvers/lns/la_lns.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/runtime/random.h"
#include "fleet_planner/solvers/registry.h"
#include "fleet_planner/solvers/search/safe_interval_search.h"
#include "fleet_planner/solvers/search/soft_path_table.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "pocket_corridor.h"
#include "solver_test_util.h"
#include "test_maps.h"
#include "tiny_worlds.h"

namespace fleet_planner::test {
namespace {

// Five robots of every footprint kind on a 12 x 12 map (where they stand matters not: the tests
// walk them at random from there).
std::vector<Robot> mixedRobots() {
  return {dot("d", {1, 1, 0}, {1, 1, 0}), bar("b", {5, 5, 0}, {5, 5, 0}),
          triangle("p", {9, 2, 1}, {9, 2, 1}),
          makeRobot("c", Footprint::circle(0.9), {3, 8, 2}, {3, 8, 2}),
          bar("e", {8, 9, 1}, {8, 9, 1})};
}

// The table's collision graph is the one the backends' own conflict code finds, on random walks
// of robots of every footprint kind, of different lengths (ended paths stay put); walks of up
// to 12 steps and of up to 1,200 (past the table's blocks of steps, kBlockSteps, and its last
// block).
TEST(SoftPathTable, PartnersAgreeWithConflictingPairs) {
  for (const int max_steps : {12, 1200}) {
  SCOPED_TRACE(max_steps);
  const World w(freeMap(12, 12), mixedRobots());
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  Rng rng(5);
  int pairs_seen = 0;
  for (int round = 0; round < (max_steps > 12 ? 20 : 200); ++round) {
    std::vector<StatePath> paths;
    SoftPathTable table(space);
    for (int a = 0; a < space.numAgents(); ++a) {
      paths.push_back(randomWalk(space, a, static_cast<int>(rng.uniformInt(0, max_steps)), rng));
      table.insert(a, paths.back());
    }
    // Remove and re-insert one agent: the index must forget its old entries.
    table.remove(2);
    table.insert(2, paths[2]);
    const std::vector<std::pair<int, int>> from_table = partnerPairs(table, space.numAgents());
    ASSERT_EQ(from_table, conflictingPairs(space, paths)) << "round " << round;
    pairs_seen += static_cast<int>(from_table.size());
  }
  EXPECT_GT(pairs_seen, 50) << "the walks should collide often enough to test something";
  }
}

// The agents met while holding a state from step t on (the soft search's goal test) are those
// met by waiting there at some step from t until everybody has stopped, step by step.
TEST(SoftPathTable, HoldingAgreesWithStepQueries) {
  const World w(freeMap(12, 12), mixedRobots());
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  Rng rng(11);
  int met_seen = 0;
  for (int round = 0; round < 100; ++round) {
    SoftPathTable table(space);
    std::vector<StateId> places;  // robot 0 where the others pass, so that they meet
    for (int a = 1; a < space.numAgents(); ++a) {
      const StatePath walk = randomWalk(space, a, static_cast<int>(rng.uniformInt(0, 12)), rng);
      table.insert(a, walk);
      for (StateId q : walk) {
        const StateId s = space.graph(0).id(space.graph(a).pose(q));
        if (s != kNoState && space.distance(0, s) >= 0) places.push_back(s);
      }
    }
    for (StateId s : places) {
      const int t = static_cast<int>(rng.uniformInt(0, 12));
      std::vector<int> holding;
      table.collisionsHolding(0, s, t, holding);
      std::sort(holding.begin(), holding.end());
      std::vector<int> stepwise;
      for (int step = t; step <= std::max(t, table.lastMove() + 1); ++step)
        table.collisions(0, s, Action::Wait, step, stepwise);
      std::sort(stepwise.begin(), stepwise.end());
      stepwise.erase(std::unique(stepwise.begin(), stepwise.end()), stepwise.end());
      ASSERT_EQ(holding, stepwise) << "round " << round << ", from step " << t;
      met_seen += static_cast<int>(holding.size());
    }
  }
  EXPECT_GT(met_seen, 100) << "the robots should meet often enough to test something";
}

// The per-cell spans that the safe interval search reads say the same as a step-by-step query:
// for random placements and actions of one robot among random walks of the others (waits
// included, so runs of several steps occur), a step is unsafe exactly when some run, some
// marked bit or the "for good" bound covers it.
TEST(SoftPathTable, UnsafeRunsAgreeWithStepQueries) {
  const World w(freeMap(12, 12), mixedRobots());
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  Rng rng(9);
  int unsafe_seen = 0;
  // One table for every round: what it keeps from the queries of a round must follow the paths
  // taken out (about half of them, put in again a round later). The asking agent is in it every
  // other round (its own path is then left out of the answers).
  SoftPathTable table(space);
  for (int round = 0; round < 100; ++round) {
    for (int a = 0; a < space.numAgents(); ++a) {
      const bool wanted = a > 0 || round % 2 == 1;
      if (table.contains(a) && (!wanted || rng.uniformInt(0, 1) == 0)) {
        table.remove(a);  // out for this round
        continue;
      }
      if (!wanted || table.contains(a)) continue;
      StatePath walk = randomWalk(space, a, static_cast<int>(rng.uniformInt(0, 12)), rng);
      // Long waits: repeat some states.
      StatePath path;
      for (StateId s : walk)
        path.insert(path.end(), static_cast<std::size_t>(rng.uniformInt(1, 3)), s);
      table.insert(a, path);
    }
    const StatePath mine = randomWalk(space, 0, 20, rng);
    for (StateId s : mine) {
      for (Action act : {Action::Wait, Action::Forward, Action::RotateCcw, Action::RotateCw}) {
        if (space.graph(0).next(s, act) == kNoState && act != Action::Wait) continue;
        std::vector<std::pair<int, int>> runs;
        int forever = 0;
        table.unsafeRuns(0, s, act, runs, forever);
        // From a later step on: the same steps from there, none before; as runs and as bits.
        const int from = static_cast<int>(rng.uniformInt(0, table.lastMove() + 2));
        std::vector<std::pair<int, int>> later;
        int later_forever = 0, lo = SoftPathTable::kNever, hi = -1, marked_forever = SoftPathTable::kNever;
        table.unsafeRuns(0, s, act, later, later_forever, from);
        std::vector<std::uint64_t> bits(static_cast<std::size_t>(table.lastMove() + 2) / 64 + 1, 0);
        table.markUnsafe(0, s, act, bits.data(), lo, hi, marked_forever, from);
        for (const auto& run : later) ASSERT_GE(run.first, from);
        for (int t = 0; t <= table.lastMove() + 3; ++t) {
          std::vector<int> met;
          table.collisions(0, s, act, t, met);
          bool covered = t >= forever;
          for (const auto& [first, last] : runs) covered = covered || (first <= t && t <= last);
          ASSERT_EQ(covered, !met.empty()) << "round " << round << ", step " << t;
          unsafe_seen += covered ? 1 : 0;
          if (t < from) continue;
          bool covered_later = t >= later_forever;
          for (const auto& [first, last] : later) covered_later = covered_later || (first <= t && t <= last);
          ASSERT_EQ(covered_later, covered) << "from " << from << ", step " << t;
          const bool bit = t >= marked_forever || (t <= table.lastMove() && ((bits[t / 64] >> (t % 64)) & 1));
          ASSERT_EQ(bit, covered) << "marked from " << from << ", step " << t;
        }
      }
    }
  }
  EXPECT_GT(unsafe_seen, 100) << "the robots should meet often enough to test something";
}

// A 1-wide corridor with one side pocket at x = 6: the runner drives the whole corridor on its
// shortest path while the other robot stands in its way at x = 7. The waiter must drive into
// the pocket before the runner reaches it, wait there until the runner has passed, and only
// then drive to its target behind it; the wait is one node of the safe interval search.
TEST(SafeIntervalSearch, WaitsInPocketUntilRunnerPassed) {
  const PocketCorridor c(dot("waiter", {7, 0, 1}, {10, 0, 0}));
  const World& w = c.w;
  const SearchSpace& space = c.space;
  ASSERT_FALSE(c.runner.empty());
  const SafeIntervalResult r = safeIntervalSearch(space, 1, c.table, Deadline::in(5.0), 100000);
  ASSERT_EQ(r.outcome, SafeIntervalResult::Outcome::Found);
  std::vector<StatePath> paths{c.runner, r.path};
  EXPECT_EQ(conflictingPairs(space, paths).size(), 0u);
  Plan plan;
  for (int a = 0; a < 2; ++a) {
    Path p;
    for (StateId s : paths[a]) p.push_back(space.graph(a).pose(s));
    plan.paths.push_back(p);
  }
  const ValidationResult v = validatePlan(w.map, w.instance, plan);
  EXPECT_TRUE(v.valid()) << v.violation.message;
  bool in_pocket = false;
  for (StateId s : r.path) in_pocket = in_pocket || space.graph(1).pose(s).y == 1;
  EXPECT_TRUE(in_pocket) << "the waiter can only let the runner by from the pocket";
}

// The plan of a moving obstacle (robot 0) and the path found for agent 0 of `space` (robot 1),
// through the validator.
ValidationResult validateAroundObstacle(const World& w, const SearchSpace& space, const Path& obstacle,
                                        const StatePath& path) {
  Plan plan;
  plan.paths.push_back(obstacle);
  Path p;
  for (StateId s : path) p.push_back(space.graph(0).pose(s));
  plan.paths.push_back(p);
  return validatePlan(w.map, w.instance, plan);
}

// A corridor of 8 cells: a robot of another subproblem (the blocker) stands at x = 3 until step
// `wait`, then drives to the end; the waiter, the subproblem's only robot, goes from x = 0 to 6.
struct BlockedCorridor {
  explicit BlockedCorridor(int wait)
      : w(freeMap(8, 1), {dot("blocker", {3, 0, 0}, {7, 0, 0}), dot("waiter", {0, 0, 0}, {6, 0, 0})}),
        sub(waiterAround(wait)),
        space(sub),
        table(space) {}

  Subproblem waiterAround(int wait) const {
    Subproblem out = allRobots(w);
    out.robots = {1};
    MovingObstacle m;
    m.robot = 0;
    m.path.assign(static_cast<std::size_t>(wait) + 1, GridPose{3, 0, 0});
    for (int x = 4; x <= 7; ++x) m.path.push_back({x, 0, 0});
    out.moving.push_back(m);
    return out;
  }

  World w;
  Subproblem sub;
  SearchSpace space;
  SoftPathTable table;
};

// The waiter leaves right after the blocker, whether the reservations end within the steps the
// search unites through a bitset (4,096) or beyond them.
TEST(SafeIntervalSearch, WaitsForAMovingObstacleShortOrLong) {
  for (int wait : {40, 5000}) {
    const BlockedCorridor c(wait);
    const SafeIntervalResult r = safeIntervalSearch(c.space, 0, c.table, Deadline::in(5.0), 100000);
    ASSERT_EQ(r.outcome, SafeIntervalResult::Outcome::Found) << "wait " << wait;
    // One cell behind the blocker (sweeps of a step may not share a cell): x = 6 at step
    // wait + 5, the step after the blocker has parked at x = 7.
    EXPECT_EQ(static_cast<int>(r.path.size()), wait + 6) << "wait " << wait;
    const ValidationResult v = validateAroundObstacle(c.w, c.space, c.sub.moving[0].path, r.path);
    EXPECT_TRUE(v.valid()) << "wait " << wait << ": " << v.violation.message;
  }
}

// The same corridor with a bound on the arrival: a bound at the earliest arrival finds it, one
// step below answers NoPath, after fewer expansions than the unbounded search needs to arrive.
TEST(SafeIntervalSearch, ArrivalBoundPrunesLaterArrivals) {
  const int wait = 40, earliest = wait + 5;
  const BlockedCorridor c(wait);
  const SafeIntervalResult free = safeIntervalSearch(c.space, 0, c.table, Deadline::in(5.0), 100000);
  ASSERT_EQ(free.outcome, SafeIntervalResult::Outcome::Found);
  ASSERT_EQ(static_cast<int>(free.path.size()) - 1, earliest);
  const SafeIntervalResult at = safeIntervalSearch(c.space, 0, c.table, Deadline::in(5.0), 100000, earliest);
  ASSERT_EQ(at.outcome, SafeIntervalResult::Outcome::Found);
  EXPECT_EQ(at.path, free.path);
  const SafeIntervalResult before =
      safeIntervalSearch(c.space, 0, c.table, Deadline::in(5.0), 100000, earliest - 1);
  EXPECT_EQ(before.outcome, SafeIntervalResult::Outcome::NoPath);
  EXPECT_LT(before.expansions, free.expansions);
}

// A robot of another subproblem stands beside the waiter's target and drives onto it late
// (step 101), turns round there and drives back (step 104): the waiter can hold its target for
// good only after that. With a bound on the arrival, reservations after the bound still count
// as "not free for good": a bound before the end of the pass answers NoPath, a bound at or after
// the unbounded arrival finds that arrival.
TEST(SafeIntervalSearch, ArrivalBoundKeepsPassesOverTheTargetAfterIt) {
  const World w(freeMap(8, 1), {dot("passer", {7, 0, 1}, {7, 0, 0}), dot("waiter", {0, 0, 0}, {6, 0, 0})});
  Subproblem sub = allRobots(w);
  sub.robots = {1};
  MovingObstacle m;
  m.robot = 0;
  m.path.assign(101, GridPose{7, 0, 1});
  for (const GridPose& q : {GridPose{6, 0, 1}, GridPose{6, 0, 2}, GridPose{6, 0, 0}, GridPose{7, 0, 0}})
    m.path.push_back(q);
  sub.moving.push_back(m);
  const SearchSpace space(sub);
  const SoftPathTable table(space);
  const SafeIntervalResult free = safeIntervalSearch(space, 0, table, Deadline::in(5.0), 100000);
  ASSERT_EQ(free.outcome, SafeIntervalResult::Outcome::Found);
  const int earliest = static_cast<int>(free.path.size()) - 1;
  ASSERT_GT(earliest, 103) << "the waiter holds its target only after the pass";
  for (int bound : {50, 100, 102, earliest - 1}) {
    const SafeIntervalResult r = safeIntervalSearch(space, 0, table, Deadline::in(5.0), 100000, bound);
    EXPECT_EQ(r.outcome, SafeIntervalResult::Outcome::NoPath) << "bound " << bound;
  }
  for (int bound : {earliest, earliest + 50}) {
    const SafeIntervalResult r = safeIntervalSearch(space, 0, table, Deadline::in(5.0), 100000, bound);
    ASSERT_EQ(r.outcome, SafeIntervalResult::Outcome::Found) << "bound " << bound;
    EXPECT_EQ(static_cast<int>(r.path.size()) - 1, earliest) << "bound " << bound;
    const ValidationResult v = validateAroundObstacle(w, space, m.path, r.path);
    EXPECT_TRUE(v.valid()) << "bound " << bound << ": " << v.violation.message;
  }
}

// A robot of another subproblem stands on the mover's target until step 60: with a loose bound
// on the arrival (refinement's "cheaper than now"), the weighted search finds a path within
// the bound after fewer expansions than the earliest-arrival search, which first tries every
// state it could reach and wait in before step 60.
TEST(SafeIntervalSearch, WeightedSearchFindsAPathWithinTheBoundSooner) {
  const World w(freeMap(24, 24), {dot("sitter", {20, 20, 0}, {21, 20, 0}), dot("mover", {0, 0, 0}, {20, 20, 0})});
  Subproblem sub = allRobots(w);
  sub.robots = {1};
  MovingObstacle m;
  m.robot = 0;
  m.path.assign(60, GridPose{20, 20, 0});
  m.path.push_back(GridPose{21, 20, 0});
  sub.moving.push_back(m);
  const SearchSpace space(sub);
  const SoftPathTable table(space);
  const int bound = 200;
  const SafeIntervalResult earliest = safeIntervalSearch(space, 0, table, Deadline::in(5.0), 100000, bound);
  const SafeIntervalResult weighted = safeIntervalSearch(space, 0, table, Deadline::in(5.0), 100000, bound, 2.0);
  ASSERT_EQ(earliest.outcome, SafeIntervalResult::Outcome::Found);
  ASSERT_EQ(weighted.outcome, SafeIntervalResult::Outcome::Found);
  EXPECT_LE(static_cast<int>(weighted.path.size()) - 1, bound);
  EXPECT_GE(weighted.path.size(), earliest.path.size());
  EXPECT_LT(weighted.expansions * 2, earliest.expansions);
  const ValidationResult v = validateAroundObstacle(w, space, m.path, weighted.path);
  EXPECT_TRUE(v.valid()) << v.violation.message;
  // A bound below the earliest arrival still answers NoPath.
  const int first = static_cast<int>(earliest.path.size()) - 1;
  EXPECT_EQ(safeIntervalSearch(space, 0, table, Deadline::in(5.0), 100000, first - 1, 2.0).outcome,
            SafeIntervalResult::Outcome::NoPath);
}

TEST(SafeIntervalSearch, NoCollisionFreePathIsNoPath) {
  // The runner parks for good on the only way to the waiter's target.
  const World w(freeMap(7, 1),
                {dot("runner", {0, 0, 0}, {3, 0, 0}), dot("waiter", {6, 0, 1}, {0, 0, 1})});
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  SoftPathTable table(space);
  table.insert(0, {space.start(0), space.graph(0).next(space.start(0), Action::Forward)});
  const SafeIntervalResult r = safeIntervalSearch(space, 1, table, Deadline::in(5.0), 100000);
  EXPECT_EQ(r.outcome, SafeIntervalResult::Outcome::NoPath);
}

TEST(LaLns, AvoidsMovingObstacleThatParksOnItsRoute) {
  const Path mover_path{{2, 0, 2}, {2, 1, 2}};
  const World w(freeMap(5, 3), {dot("runner", {0, 1, 0}, {4, 1, 0}),
                                dot("mover", mover_path.front(), mover_path.back())});
  const std::unique_ptr<Solver> solver = makeSolver("la_lns");
  EXPECT_TRUE(solver->avoidsMovingObstacles());
  Subproblem sub = allRobots(w);
  sub.robots = {0};
  sub.moving = {{1, mover_path}};
  const Outcome o = solveWith(*solver, w, sub);
  ASSERT_TRUE(solvedValidly(o));
  Plan joint;
  joint.paths = {o.result.paths[0], mover_path};
  const ValidationResult v = validatePlan(w.map, w.instance, joint);
  EXPECT_TRUE(v.valid()) << v.violation.message;
}


// A and B swap along a corridor whose only pocket holds C, at its target. Replanned one by one,
// C has no reason to move and A and B each prefer one colliding step to waiting: the joint step
// (joint_path_search.h) unties it.
TEST(LaLns, UntiesThreeRobotKnot) {
  const World w(mapFromRows({".......", "@@@.@@@", "@@@.@@@"}),
                {dot("A", {0, 0, 0}, {6, 0, 0}), dot("B", {6, 0, 1}, {0, 0, 1}), dot("C", {3, 1, 2}, {3, 1, 2})});
  const Outcome o = solveWith("la_lns", w, allRobots(w, 5.0));
  ASSERT_TRUE(solvedValidly(o));
}

// Two robots that cannot pass each other: the joint step proves it and names them, at once.
TEST(LaLns, ProvesAnImpossibleSwapAndNamesBothRobots) {
  const World w(freeMap(6, 1), {dot("a", {0, 0, 0}, {5, 0, 0}), dot("b", {5, 0, 1}, {0, 0, 1})});
  const Outcome o = solveWith("la_lns", w, allRobots(w, 5.0));
  EXPECT_EQ(o.result.status, SolveStatus::Infeasible) << describe(o);
  EXPECT_NE(o.result.reason.find("'a'"), std::string::npos) << o.result.reason;
  EXPECT_NE(o.result.reason.find("'b'"), std::string::npos) << o.result.reason;
  EXPECT_EQ(o.result.culprits, (std::vector<int>{0, 1}));
  EXPECT_LT(o.wall_s, 1.0) << describe(o);
}

// The same swap along a longer corridor, with the joint step given 500 joint states, too few to
// exhaust its timed joint space (as on real maps with the default 50,000): the pair alone among
// the static obstacles proves it, within its share of the time even under the
// sanitizers. The third robot, at its target in the pocket at the corridor's end, is not named:
// the two cannot swap even with the pocket free.
TEST(LaLns, ProvesAnImpossibleSwapInALongCorridorByThePairAlone) {
  const World w = swapInACorridorWithAPocket(16);
  LaLnsOptions options;
  options.joint_search_nodes = 500;
  LaLns solver(options);
  const Outcome o = solveWith(solver, w, allRobots(w, 20.0));
  EXPECT_EQ(o.result.status, SolveStatus::Infeasible) << describe(o);
  EXPECT_NE(o.result.reason.find("'a' and robot 'b'"), std::string::npos) << o.result.reason;
  EXPECT_NE(o.result.reason.find("even with no other robot moving"), std::string::npos)
      << o.result.reason;
  EXPECT_EQ(o.result.culprits, (std::vector<int>{0, 1}));
}

}  // namespace
}  // namespace fleet_planner::test
