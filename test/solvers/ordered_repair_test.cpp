// The ordered joint repair of LA-LNS (ordered_repair.h): each agent keeps out of the starts of
// the agents after it, the paths together collide with nobody (checked by the plan validator),
// and an order whose first agent must pass a later one's start fails where its reverse works.
#include <gtest/gtest.h>

#include <algorithm>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/solvers/lns/ordered_repair.h"
#include "fleet_planner/solvers/search/solve_common.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

// The validator's verdict on `paths` (one per agent, in instance order).
ValidationResult validateAll(const World& w, const SearchSpace& space,
                             const std::vector<StatePath>& paths) {
  Plan plan;
  plan.paths = toPosePaths(space, paths);
  return validatePlan(w.map, w.instance, plan);
}

// Agent a on `path` collides with agent b standing at its start for good.
bool passesStartOf(const SearchSpace& space, int a, const StatePath& path, int b) {
  SoftPathTable parked(space);
  parked.insert(b, StatePath{space.start(b)});
  return !parked.partners(a, path).empty();
}

TEST(OrderedRepair, KeepsOutOfLaterStartsAndCollidesWithNobody) {
  // "t" keeps its shortest path in the table; "b"'s start is on "a"'s shortest way, and "a"'s
  // start on "c"'s.
  const World w(freeMap(10, 10), {dot("t", {0, 8, 0}, {9, 8, 0}), dot("a", {2, 5, 0}, {8, 5, 0}),
                                  dot("b", {5, 5, 3}, {5, 1, 3}), bar("c", {2, 1, 2}, {2, 8, 2})});
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  const LowLevelResult shortest = spaceTimeAStar(space, 0, AgentConstraints{}, Deadline::in(5.0));
  ASSERT_EQ(shortest.outcome, LowLevelResult::Outcome::Found);
  SoftPathTable table(space);
  table.insert(0, shortest.path);
  std::vector<int> order{1, 2, 3};
  int orders = 0;
  do {
    long long expansions = 0;
    const auto paths = orderedRepair(space, table, order, Deadline::in(5.0), 100'000, expansions);
    ASSERT_TRUE(paths.has_value()) << "order " << order[0] << order[1] << order[2];
    EXPECT_GT(expansions, 0);
    for (int a : order) EXPECT_FALSE(table.contains(a)) << "the table is left as it was";
    ASSERT_TRUE(table.contains(0));
    std::vector<StatePath> all(4);
    all[0] = shortest.path;
    for (std::size_t i = 0; i < order.size(); ++i) all[order[i]] = (*paths)[i];
    const ValidationResult v = validateAll(w, space, all);
    EXPECT_TRUE(v.valid()) << violationName(v.violation.kind) << " in order " << order[0]
                           << order[1] << order[2];
    for (std::size_t i = 0; i < order.size(); ++i) {
      for (std::size_t j = i + 1; j < order.size(); ++j) {
        EXPECT_FALSE(passesStartOf(space, order[i], (*paths)[i], order[j]))
            << space.label(order[i]) << " passes the start of " << space.label(order[j])
            << ", later in the order";
      }
    }
    ++orders;
  } while (std::next_permutation(order.begin(), order.end()));
  EXPECT_EQ(orders, 6);
}

TEST(OrderedRepair, FailsWhereTheFirstMustPassALaterStartAndWorksInReverse) {
  // A 1-wide corridor with one pocket below x = 6: "a" drives it east, through "b"'s start;
  // "b" goes into the pocket.
  const World w(mapFromRows({"..............", "@@@@@@.@@@@@@@"}),
                {dot("a", {1, 0, 0}, {13, 0, 0}), dot("b", {9, 0, 1}, {6, 1, 2})});
  const Subproblem sub = allRobots(w);
  const SearchSpace space(sub);
  SoftPathTable table(space);
  long long expansions = 0;
  EXPECT_FALSE(orderedRepair(space, table, {0, 1}, Deadline::in(5.0), 100'000, expansions));
  const auto paths = orderedRepair(space, table, {1, 0}, Deadline::in(5.0), 100'000, expansions);
  ASSERT_TRUE(paths.has_value());
  EXPECT_FALSE(table.contains(0) || table.contains(1));
  const ValidationResult v = validateAll(w, space, {(*paths)[1], (*paths)[0]});
  EXPECT_TRUE(v.valid()) << violationName(v.violation.kind);
}

}  // namespace
}  // namespace fleet_planner::test
