// The time share each subproblem gets from the layered planner (subproblem_solving.h), and
// whether it may end when it stalls.
#include <gtest/gtest.h>

#include <map>
#include <mutex>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/layered/subproblem_solving.h"
#include "fleet_planner/layered/time_budget.h"
#include "fleet_planner/solvers/registry.h"
#include "test_maps.h"
#include "test_robots.h"

namespace fleet_planner {
namespace {

using test::dot;
using test::footprintsOf;

// A test-only parallel backend: LA-LaCAM, recording the seconds each subproblem was given and
// whether it may end when stalled (by its first robot).
std::mutex given_mutex;
std::map<int, double> given;
std::map<int, bool> ends_when_stalled;

class Recording : public Solver {
 public:
  std::string name() const override { return "share_recording_test_backend"; }
  bool avoidsMovingObstacles() const override { return false; }
  SolveResult solve(const Subproblem& p) override {
    {
      const std::lock_guard<std::mutex> lock(given_mutex);
      given[p.robots.front()] = p.deadline.remaining();
      ends_when_stalled[p.robots.front()] = p.ends_when_stalled;
    }
    return makeSolver("la_lacam")->solve(p);
  }
};
const bool kRecording =
    registerSolver("share_recording_test_backend", [] { return std::make_unique<Recording>(); });

// Ten robots, each crossing its own row of a free map: six one-robot subproblems, one of three
// robots, and a last one-robot subproblem. When the three-robot subproblem starts, only it and
// the last are left: it gets three quarters of the time left, not three tenths (the robots of
// the subproblems already solved no longer count).
TEST(TimeShare, ALateSubproblemSharesOnlyWithTheRobotsStillToSolve) {
  ASSERT_TRUE(kRecording);
  const int rows = 10;
  const GridMap map = test::freeMap(12, rows);
  Instance in;
  std::vector<SolvedSubproblem> order;
  for (int r = 0; r < rows; ++r) {
    in.robots.push_back(dot("r" + std::to_string(r), {0, r, 0}, {11, r, 0}));
    if (r == 7 || r == 8) continue;  // with robot 6
    SolvedSubproblem s;
    s.robots = r == 6 ? std::vector<int>{6, 7, 8} : std::vector<int>{r};
    s.cluster = static_cast<int>(order.size());
    s.seed_offset = static_cast<std::uint64_t>(r);
    order.push_back(s);
  }
  const FleetGraphs graphs(map, footprintsOf(in));
  SubproblemSolvingOptions o;
  o.backend = "share_recording_test_backend";
  o.threads = 1;
  given.clear();
  const double seconds = 20.0;
  const SubproblemSolving solved = solveSubproblems(in, graphs, order, o, Deadline::in(seconds));
  ASSERT_EQ(solved.status, SolveStatus::Success) << solved.reason;
  EXPECT_TRUE(validatePlan(map, in, Plan{solved.paths}).valid());
  ASSERT_EQ(given.size(), 8u);
  const double minimum = TimeBudget{}.min_subproblem_share;
  ASSERT_LT(minimum, 0.6) << "the three-robot subproblem's check below needs a share above the minimum";
  EXPECT_LT(given[0], (minimum + 0.05) * seconds) << "a one-robot subproblem among ten robots: the minimum";
  EXPECT_GT(given[6], 0.6 * seconds) << "three robots of the four left";
  EXPECT_GT(given[9], 0.9 * seconds) << "the last subproblem gets all that is left";
}

// The caller's other way to plan a stalled fleet (LayeredOptions::whole_fleet_ends_when_stalled:
// the planner's coarser lattice) is told to the whole fleet solved as one subproblem, and to
// nothing smaller: a subproblem of several has the safeguard (a step aside, a merge) after it.
TEST(TimeShare, OnlyTheWholeFleetAsOneMayEndWhenItStalls) {
  ASSERT_TRUE(kRecording);
  const GridMap map = test::freeMap(12, 3);
  Instance in;
  for (int r = 0; r < 3; ++r) in.robots.push_back(dot("r" + std::to_string(r), {0, r, 0}, {11, r, 0}));
  const FleetGraphs graphs(map, footprintsOf(in));
  SolvedSubproblem whole;
  whole.robots = {0, 1, 2};
  std::vector<SolvedSubproblem> each(3);
  for (int r = 0; r < 3; ++r) {
    each[r].robots = {r};
    each[r].cluster = r;
    each[r].seed_offset = static_cast<std::uint64_t>(r);
  }
  for (const bool another_way : {true, false}) {
    SubproblemSolvingOptions o;
    o.backend = "share_recording_test_backend";
    o.whole_fleet_ends_when_stalled = another_way;
    ends_when_stalled.clear();
    ASSERT_EQ(solveSubproblems(in, graphs, {whole}, o, Deadline::in(20.0)).status, SolveStatus::Success);
    EXPECT_EQ(ends_when_stalled, (std::map<int, bool>{{0, another_way}}));
    ends_when_stalled.clear();
    ASSERT_EQ(solveSubproblems(in, graphs, each, o, Deadline::in(20.0)).status, SolveStatus::Success);
    EXPECT_EQ(ends_when_stalled, (std::map<int, bool>{{0, false}, {1, false}, {2, false}}));
  }
}

}  // namespace
}  // namespace fleet_planner
