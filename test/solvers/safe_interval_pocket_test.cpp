// A way to a pocket that another robot passes late (safeIntervalPocket): the robot arrives
// after that pass and holds the pocket for good, without waiting for a robot that moves
// elsewhere until much later.
#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#include "fleet_planner/solvers/search/safe_interval_search.h"
#include "fleet_planner/solvers/search/soft_path_table.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

// On a free 100 x 40 map, robot "pushed" at (5, 2) is to park at (20, 5) (its target too, for the
// validator; the search's heuristic is the pocket's lower bound of steps). Robot "late" waits at
// (20, 9) until step `wait`, then drives down the column x = 20 to (20, 1), over the pocket. Robot
// "busy", far away at (60, 30), moves one cell at step `busy_until`: the plan's last move.
struct LatePocketPass {
  explicit LatePocketPass(int wait = 150, int busy_until = 400)
      : world(freeMap(100, 40), {dot("pushed", {5, 2, 0}, {20, 5, 0}), dot("late", {20, 9, 3}, {20, 1, 3}),
                                dot("busy", {60, 30, 0}, {61, 30, 0})}),
        sub(allRobots(world)),
        space(sub),
        table(space) {
    for (int t = 0; t <= wait; ++t) late.push_back(state(1, {20, 9, 3}));
    for (int y = 8; y >= 1; --y) late.push_back(state(1, {20, y, 3}));
    for (int t = 0; t < busy_until; ++t) busy.push_back(space.start(2));
    busy.push_back(space.target(2));
    table.insert(1, late);
    table.insert(2, busy);
  }
  StateId state(int a, const GridPose& p) const { return space.graph(a).id(p); }
  StateId pocket() const { return state(0, {20, 5, 0}); }
  // The step from which the pocket is free for good: late has left it.
  int ready() const { return static_cast<int>(late.size()) - 4; }
  SafeIntervalResult toPocket(StateId to) const {
    return safeIntervalPocket(space, 0, table, space.start(0), 0, to, Deadline::in(5.0), 1'000'000);
  }
  // The pushed robot's path held at its end for as long as the others' paths last.
  ValidationResult validateHeld(StatePath path) const {
    path.resize(std::max(path.size(), busy.size() + 1), path.back());
    return validateStatePaths(world, sub, space, {path, late, busy});
  }

  World world;
  Subproblem sub;
  SearchSpace space;
  SoftPathTable table;
  StatePath late, busy;
};

int arrival(const StatePath& path) { return static_cast<int>(path.size()) - 1; }

TEST(SafeIntervalPocket, ArrivesAfterTheLastPassOverThePocketAndHoldsIt) {
  const LatePocketPass w;
  const SafeIntervalResult found = w.toPocket(w.pocket());
  ASSERT_EQ(found.outcome, SafeIntervalResult::Outcome::Found);
  ASSERT_FALSE(found.path.empty());
  EXPECT_EQ(found.path.front(), w.space.start(0));
  EXPECT_EQ(found.path.back(), w.pocket());
  const ValidationResult valid = w.validateHeld(found.path);
  EXPECT_TRUE(valid.valid()) << valid.violation.message;
  // After the pass, within its steps to the pocket plus kHomeLeadSteps of it (it departs
  // late, from where it stands), and long before the plan's last move elsewhere.
  const int steps = 15 + 3 + 1;  // |dx| + |dy| + one rotation: a lower bound
  EXPECT_GE(arrival(found.path), w.ready());
  EXPECT_LE(arrival(found.path), w.ready() + steps + kHomeLeadSteps);
  EXPECT_LT(arrival(found.path), static_cast<int>(w.busy.size()) - 1);
}

TEST(SafeIntervalPocket, ArrivesAtTheEarliestWhenNobodyPassesThePocket) {
  const LatePocketPass w(/*wait=*/0);  // late passes at once, before the pushed robot gets there
  const SafeIntervalResult found = w.toPocket(w.pocket());
  ASSERT_EQ(found.outcome, SafeIntervalResult::Outcome::Found);
  const SafeIntervalResult earliest = safeIntervalSegment(w.space, 0, w.table, w.space.start(0), 0, w.pocket(), 0,
                                                          SoftPathTable::kNever / 2, Deadline::in(5.0), 1'000'000);
  ASSERT_EQ(earliest.outcome, SafeIntervalResult::Outcome::Found);
  EXPECT_EQ(arrival(found.path), arrival(earliest.path));
  const ValidationResult valid = w.validateHeld(found.path);
  EXPECT_TRUE(valid.valid()) << valid.violation.message;
}

TEST(SafeIntervalPocket, FindsNoWayToAPocketWhereSomebodyEnds) {
  const LatePocketPass w;
  // late's last pose: it stands there for good.
  const SafeIntervalResult found = w.toPocket(w.state(0, {20, 1, 0}));
  EXPECT_EQ(found.outcome, SafeIntervalResult::Outcome::NoPath);
}

}  // namespace
}  // namespace fleet_planner::test
