// A way home whose target another robot passes late (safeIntervalHome): the robot waits where
// it stands and departs shortly before the target is free for good, instead of searching every
// state it could wait in before then.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "fleet_planner/solvers/search/safe_interval_search.h"
#include "fleet_planner/solvers/search/soft_path_table.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

// On a free 100 x 40 map, robot "late" waits at (20, 9) until `wait`, then drives down the
// column x = 20 to (20, 1), over the target (20, 5) of robot "home", which starts at (5, 2). Robot "early", with
// `cross`, drives down the column x = 5 from (5, 9) to (5, 0) at once, over home's start;
// otherwise it stands at (38, 9).
struct LatePass {
  explicit LatePass(int wait = 150, bool cross = false)
      : world(freeMap(100, 40), {dot("home", {5, 2, 0}, {20, 5, 0}), dot("late", {20, 9, 3}, {20, 1, 3}),
                                cross ? dot("early", {5, 9, 3}, {5, 0, 3}) : dot("early", {38, 9, 3}, {38, 9, 3})}),
        sub(allRobots(world)),
        space(sub),
        table(space) {
    for (int t = 0; t < wait; ++t) late.push_back(state(1, {20, 9, 3}));
    for (int y = 8; y >= 1; --y) late.push_back(state(1, {20, y, 3}));
    early.push_back(space.start(2));
    for (int y = 8; cross && y >= 0; --y) early.push_back(state(2, {5, y, 3}));
    table.insert(1, late);
    table.insert(2, early);
  }
  StateId state(int a, const GridPose& p) const { return space.graph(a).id(p); }
  // The step from which the target is free for good: late has left it.
  int ready() const { return static_cast<int>(late.size()) - 4; }
  SafeIntervalResult earliest() const {
    return safeIntervalSegment(space, 0, table, space.start(0), 0, space.target(0), SoftPathTable::kNever, 0,
                               Deadline::in(5.0), 1'000'000);
  }
  SafeIntervalResult home() const {
    return safeIntervalHome(space, 0, table, space.start(0), 0, Deadline::in(5.0), 1'000'000);
  }
  ValidationResult validate(const StatePath& path) const {
    return validateStatePaths(world, sub, space, {path, late, early});
  }

  World world;
  Subproblem sub;
  SearchSpace space;
  SoftPathTable table;
  StatePath late, early;
};

int arrival(const StatePath& path) { return static_cast<int>(path.size()) - 1; }

TEST(SafeIntervalHome, WaitsWhereItStandsWhenItsTargetIsPassedLate) {
  const LatePass w;
  const SafeIntervalResult earliest = w.earliest();
  const SafeIntervalResult home = w.home();
  ASSERT_EQ(earliest.outcome, SafeIntervalResult::Outcome::Found);
  ASSERT_EQ(home.outcome, SafeIntervalResult::Outcome::Found);
  ASSERT_FALSE(home.path.empty());
  EXPECT_EQ(home.path.front(), w.space.start(0));
  EXPECT_EQ(home.path.back(), w.space.target(0));
  const ValidationResult valid = w.validate(home.path);
  EXPECT_TRUE(valid.valid()) << valid.violation.message;
  // It arrives after the last pass, and no later than its distance plus kHomeLeadSteps after it.
  const int d = w.space.distance(0, w.space.start(0));
  EXPECT_GE(arrival(home.path), w.ready());
  EXPECT_LE(arrival(home.path), std::max(arrival(earliest.path), w.ready() + d + kHomeLeadSteps));
  // The earliest arrival searches the space-time cone below the last pass; this way does not.
  EXPECT_LT(home.expansions * 4, earliest.expansions)
      << home.expansions << " expansions against " << earliest.expansions;
}

TEST(SafeIntervalHome, SearchesTheEarliestArrivalWhenItCannotWaitWhereItStands) {
  const LatePass w(150, /*cross=*/true);  // early drives over home's start at once
  const SafeIntervalResult earliest = w.earliest();
  const SafeIntervalResult home = w.home();
  ASSERT_EQ(home.outcome, SafeIntervalResult::Outcome::Found);
  EXPECT_EQ(home.path, earliest.path);
  EXPECT_EQ(home.expansions, earliest.expansions);
  const ValidationResult valid = w.validate(home.path);
  EXPECT_TRUE(valid.valid()) << valid.violation.message;
}

TEST(SafeIntervalHome, IsTheEarliestArrivalWhenItsTargetIsFreeSoonEnough) {
  const LatePass w(/*wait=*/10);
  const SafeIntervalResult home = w.home();
  ASSERT_EQ(home.outcome, SafeIntervalResult::Outcome::Found);
  EXPECT_EQ(home.path, w.earliest().path);
}

// Nobody can hold the target before late has left it: the earliest arrival for good is the
// step after (a move into the target during the step late leaves it would meet late).
TEST(SafeIntervalHome, ArrivesForGoodNoEarlierThanTheLastPassAllows) {
  const LatePass w;
  const SafeIntervalResult earliest = w.earliest();
  ASSERT_EQ(earliest.outcome, SafeIntervalResult::Outcome::Found);
  EXPECT_EQ(earliestArrivalForGood(w.space, 0, w.table), w.ready() + 1);
  EXPECT_EQ(arrival(earliest.path), earliestArrivalForGood(w.space, 0, w.table));
}

// A search bounded before that arrival finds nothing, and knows it without a single expansion
// (the states it could wait in before the last pass are many).
TEST(SafeIntervalHome, ABoundBeforeTheLastPassIsNoPathAtOnce) {
  const LatePass w;
  const int bound = earliestArrivalForGood(w.space, 0, w.table);
  const SafeIntervalResult before =
      safeIntervalSearch(w.space, 0, w.table, Deadline::in(5.0), 1'000'000, bound - 1);
  EXPECT_EQ(before.outcome, SafeIntervalResult::Outcome::NoPath);
  EXPECT_EQ(before.expansions, 0);
  const SafeIntervalResult at = safeIntervalSearch(w.space, 0, w.table, Deadline::in(5.0), 1'000'000, bound);
  ASSERT_EQ(at.outcome, SafeIntervalResult::Outcome::Found);
  EXPECT_EQ(arrival(at.path), bound);
}

}  // namespace
}  // namespace fleet_planner::test
