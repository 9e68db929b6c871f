// The time share each subproblem gets from the layered planner (subproblem_solving.h).
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

// A test-only parallel backend: LA-LaCAM, recording the seconds each subproblem was given (by
// its first robot).
std::mutex given_mutex;
std::map<int, double> given;

class Recording : public Solver {
 public:
  std::string name() const override { return "share_recording_test_backend"; }
  bool avoidsMovingObstacles() const override { return false; }
  SolveResult solve(const Subproblem& p) override {
    {
      const std::lock_guard<std::mutex> lock(given_mutex);
      given[p.robots.front()] = p.deadline.remaining();
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

}  // namespace
}  // namespace fleet_planner
