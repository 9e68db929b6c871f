// The earliest schedule (earliest_schedule.h): the exact retiming of a hand-made plan, and on the
// random planned worlds slowed down to half speed: valid plans with the same poses in the same
// order, no robot later than in the plan it was given, the same result every time.
#include "fleet_planner/execution/earliest_schedule.h"

#include <gtest/gtest.h>

#include "execution_worlds.h"

namespace fleet_planner::test {
namespace {

// The poses a path visits, waits dropped.
Path posesOf(const Path& p) {
  Path out;
  for (const GridPose& s : p)
    if (out.empty() || !(out.back() == s)) out.push_back(s);
  return out;
}

// The time a path reaches its last pose.
int arrivalOf(const Path& p) {
  int t = static_cast<int>(p.size()) - 1;
  while (t > 0 && p[t - 1] == p.back()) --t;
  return t;
}

std::vector<Path> earliestOf(const Instance& instance, const Plan& plan, const ActionModel& model = {}) {
  const PlanCells cells(instance, plan, model);
  const std::optional<std::vector<Path>> paths = earliestSchedule(cells, buildStepDependencies(cells));
  EXPECT_TRUE(paths.has_value());
  return paths.value_or(std::vector<Path>{});
}

TEST(EarliestSchedule, AFollowerWaitsOnlyAsLongAsTheLeaderIsInItsWay) {
  // A corridor of one row: a drives right from cell 1; b, on cell 0, waits four steps before it
  // follows, where one is needed (it must not enter cell 1 while a's first move sweeps it).
  const GridMap map = freeMap(5, 1);
  Instance in;
  in.robots = {dot("a", {1, 0, 0}, {4, 0, 0}), dot("b", {0, 0, 0}, {3, 0, 0})};
  Plan plan;
  plan.paths = {{{1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}},
                {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}};
  ASSERT_TRUE(validatePlan(map, in, plan).valid());
  const std::vector<Path> paths = earliestOf(in, plan);
  ASSERT_EQ(paths.size(), 2u);
  EXPECT_EQ(paths[0], plan.paths[0]);
  EXPECT_EQ(paths[1], (Path{{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}));
}

// The plan at half speed: every step followed by a wait of every robot at once. Still valid
// (at each added step every robot stands where the plan has it at that time).
Plan halfSpeed(const Plan& plan) {
  std::size_t horizon = 0;
  for (const Path& p : plan.paths) horizon = std::max(horizon, p.size());
  Plan slow;
  for (const Path& p : plan.paths) {
    Path q;
    for (std::size_t t = 0; t < horizon; ++t) {
      q.push_back(stateAt(p, static_cast<int>(t)));
      if (t + 1 < horizon) q.push_back(stateAt(p, static_cast<int>(t)));
    }
    slow.paths.push_back(std::move(q));
  }
  return slow;
}

TEST(EarliestSchedule, RandomPlansAtHalfSpeedComeBackValidAndNoLater) {
  ASSERT_GE(testWorlds().size(), 10u);
  for (const PlannedWorld& w : testWorlds()) {
    const Plan slow = halfSpeed(w.plan);
    ASSERT_TRUE(validatePlan(w.map, w.instance, slow, w.model).valid()) << w.name;
    Plan fast;
    fast.paths = earliestOf(w.instance, slow, w.model);
    ASSERT_EQ(fast.paths.size(), w.plan.paths.size()) << w.name;
    const ValidationResult check = validatePlan(w.map, w.instance, fast, w.model);
    EXPECT_TRUE(check.valid()) << w.name << ": " << check.violation.message;
    for (std::size_t i = 0; i < fast.paths.size(); ++i) {
      EXPECT_EQ(posesOf(fast.paths[i]), posesOf(w.plan.paths[i])) << w.name << ", robot " << i;
      EXPECT_LE(arrivalOf(fast.paths[i]), arrivalOf(w.plan.paths[i])) << w.name << ", robot " << i;
    }
    EXPECT_EQ(earliestOf(w.instance, slow, w.model), fast.paths) << w.name;
  }
}

}  // namespace
}  // namespace fleet_planner::test
