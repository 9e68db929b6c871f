// The second lattice (plan_fleet.h): a fleet that times out on its default lattice is planned in
// the rest of the call on a lattice twice as coarse; a lattice the caller chose gets the whole
// call; when the coarser lattice fails too, the first answer stands, with a note. The default
// lattice's share is set to nothing here, so that its attempt times out on every machine. A
// whole fleet on the default lattice is told that a coarser one follows (it may end when it
// stalls).
#include <gtest/gtest.h>

#include <mutex>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/planning/plan_fleet.h"
#include "fleet_planner/solvers/registry.h"
#include "test_maps.h"
#include "test_robots.h"
#include "valid_on_cells.h"

namespace fleet_planner::test {
namespace {

/// A square robot 6 cells across: the default lattice is 2 (a third of its width).
Robot square(const std::string& id, GridPose start, GridPose target) {
  return makeRobot(id, Footprint::block(-3, -3, 3, 3), start, target);
}

PlanningOptions defaultLatticeWithoutTime() {
  PlanningOptions o;
  o.threads = 1;
  o.time_limit = 20.0;
  o.budget.default_lattice_share = 1e-9;
  return o;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

Instance crossing() {
  Instance instance;
  instance.robots = {square("a", {6, 12, 0}, {54, 12, 0}), square("b", {30, 5, 1}, {30, 18, 1})};
  return instance;
}

TEST(SecondLattice, AFleetThatTimesOutOnTheDefaultLatticeIsPlannedOnOneTwiceAsCoarse) {
  const GridMap map = freeMap(60, 24);
  const Instance instance = crossing();
  const PlanningResult r = planFleet(map, instance, defaultLatticeWithoutTime());
  ASSERT_TRUE(validOnCells(map, instance, r));
  EXPECT_EQ(r.lattice_step, 4);
  ASSERT_EQ(r.lattice_notes.size(), 1u);
  EXPECT_TRUE(contains(r.lattice_notes[0], "step 2: timed out")) << r.lattice_notes[0];
  EXPECT_TRUE(contains(r.lattice_notes[0], "planned on step 4")) << r.lattice_notes[0];
  ASSERT_NE(r.graphs, nullptr);
  EXPECT_EQ(r.graphs->graph(0).actionModel().step, 4)
      << "the graphs of the plan's lattice, for re-planning";
}

TEST(SecondLattice, ALatticeTheCallerChoseGetsTheWholeCall) {
  const GridMap map = freeMap(60, 24);
  const Instance instance = crossing();
  PlanningOptions o = defaultLatticeWithoutTime();
  o.lattice_step = 2;
  const PlanningResult r = planFleet(map, instance, o);
  ASSERT_TRUE(validOnCells(map, instance, r));
  EXPECT_EQ(r.lattice_step, 2);
  EXPECT_TRUE(r.lattice_notes.empty()) << r.lattice_notes.front();
}

TEST(SecondLattice, WhenTheCoarserLatticeFailsTooTheFirstAnswerStands) {
  // Walls at x = 20 and x = 32, closed but for a door 7 cells wide in each, the second 2 cells
  // lower: the robot shifts sideways by 1-3 cells between them, which a lattice of 2 allows and
  // one of 4 does not.
  std::vector<std::string> rows(30, std::string(52, '.'));
  for (int y = 0; y < 30; ++y) {
    if (y < 10 || y > 16) rows[y][20] = '@';
    if (y < 12 || y > 18) rows[y][32] = '@';
  }
  const GridMap map = mapFromRows(rows);
  Instance instance;
  instance.robots = {square("r", {6, 13, 0}, {46, 15, 0})};
  const PlanningResult r = planFleet(map, instance, defaultLatticeWithoutTime());
  EXPECT_EQ(r.status, SolveStatus::Timeout) << r.reason;
  EXPECT_FALSE(r.reason.empty());
  ASSERT_EQ(r.lattice_notes.size(), 1u);
  EXPECT_TRUE(contains(r.lattice_notes[0], "step 2: timed out")) << r.lattice_notes[0];
  EXPECT_TRUE(contains(r.lattice_notes[0], "step 4 tried in the rest of the time"))
      << r.lattice_notes[0];
  EXPECT_TRUE(contains(r.lattice_notes[0], "'r'")) << r.lattice_notes[0];
  // With the default share the default lattice plans it.
  PlanningOptions o = defaultLatticeWithoutTime();
  o.budget.default_lattice_share = TimeBudget{}.default_lattice_share;
  const PlanningResult planned = planFleet(map, instance, o);
  ASSERT_TRUE(validOnCells(map, instance, planned));
  EXPECT_EQ(planned.lattice_step, 2);
}

// A test-only backend: LA-LNS, recording Subproblem::ends_when_stalled of every call.
std::mutex told_mutex;
std::vector<bool> told;

class TellsEnd : public Solver {
 public:
  std::string name() const override { return "ends_when_stalled_test_backend"; }
  bool avoidsMovingObstacles() const override { return true; }
  SolveResult solve(const Subproblem& p) override {
    {
      const std::lock_guard<std::mutex> lock(told_mutex);
      told.push_back(p.ends_when_stalled);
    }
    return makeSolver("la_lns")->solve(p);
  }
};
const bool kTellsEnd = registerSolver("ends_when_stalled_test_backend", [] { return std::make_unique<TellsEnd>(); });

TEST(SecondLattice, AWholeFleetOnTheDefaultLatticeMayEndWhenItStalls) {
  ASSERT_TRUE(kTellsEnd);
  const GridMap map = freeMap(60, 24);
  const Instance instance = crossing();
  for (const int chosen : {0, 2}) {
    SCOPED_TRACE(chosen == 0 ? "default lattice (2), a coarser one follows" : "lattice 2 chosen");
    PlanningOptions o;
    o.threads = 1;
    o.time_limit = 20.0;
    o.decompose = false;  // the whole fleet as one subproblem
    o.backend = "ends_when_stalled_test_backend";
    o.fallback = "";
    o.lattice_step = chosen;
    told.clear();
    const PlanningResult r = planFleet(map, instance, o);
    ASSERT_TRUE(validOnCells(map, instance, r));
    EXPECT_EQ(r.lattice_step, 2);
    ASSERT_FALSE(told.empty());
    for (const bool t : told) EXPECT_EQ(t, chosen == 0);
  }
}

}  // namespace
}  // namespace fleet_planner::test
