// Lattice plans on steps of one cell (cell_steps.h): each lattice step becomes `step` cell steps,
// the plans stay valid on the map's cells under the model of step 1, and the facade returns
// them retimed, never dearer than the lattice's plan at the same speed.
#include "fleet_planner/planning/cell_steps.h"

#include <gtest/gtest.h>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/model/robot_cells.h"
#include "fleet_planner/runtime/errors.h"
#include "lattice_worlds.h"
#include "valid_on_cells.h"

namespace fleet_planner::test {
namespace {

ActionModel stepOf(int step, bool backward = false) {
  ActionModel m;
  m.step = step;
  m.allow_backward = backward;
  return m;
}

TEST(CellSteps, EachLatticeStepBecomesStepCellSteps) {
  // On lattice step 3: a move of 3, a turn, a wait, a move of 3 along +y, a short move of 2.
  Plan lattice;
  lattice.paths = {{{0, 0, 0}, {3, 0, 0}, {3, 0, 2}, {3, 0, 2}, {3, 3, 2}, {3, 5, 2}}};
  const Plan fine = onCellSteps(lattice, stepOf(3));
  const Path expected = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0},  // move of 3
                         {3, 0, 2}, {3, 0, 2}, {3, 0, 2},             // turn, 2 waits
                         {3, 0, 2}, {3, 0, 2}, {3, 0, 2},             // wait, 2 waits
                         {3, 1, 2}, {3, 2, 2}, {3, 3, 2},             // move of 3
                         {3, 4, 2}, {3, 5, 2}};                       // the last, short, unpadded
  ASSERT_EQ(fine.paths.size(), 1u);
  EXPECT_EQ(fine.paths[0], expected);
  // Backward moves go against the heading, one cell a step; a one-pose path stays as it is.
  Plan back;
  back.paths = {{{9, 4, 0}, {7, 4, 0}, {7, 4, 0}}, {{2, 2, 1}}};
  const Plan fine_back = onCellSteps(back, stepOf(2, true));
  EXPECT_EQ(fine_back.paths[0], (Path{{9, 4, 0}, {8, 4, 0}, {7, 4, 0}, {7, 4, 0}}));
  EXPECT_EQ(fine_back.paths[1], back.paths[1]);
  // Step 1 is the plan itself.
  EXPECT_EQ(onCellSteps(lattice, stepOf(1)).paths, lattice.paths);
}

TEST(CellSteps, AStepThatIsNoMotionOnTheLatticeIsNamed) {
  Plan plan;
  plan.paths = {{{0, 0, 0}, {1, 0, 0}}, {{5, 5, 0}, {5, 5, 0}, {9, 5, 0}}};
  try {
    onCellSteps(plan, stepOf(3));
    FAIL() << "a move of 4 cells on lattice step 3 was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("robot 1: step 1"), std::string::npos) << e.what();
  }
}

TEST(CellSteps, LatticePlansStayValidOnCellStepsAndKeepTheirPosesInTime) {
  int checked = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const RandomWorld world(6, seed);
    for (int step : {2, 3, 5}) {
      PlanningOptions o = onLattice(step);
      o.cell_steps = false;
      const PlanningResult r = planFleet(world.map, world.instance, o);
      if (!r.success() || r.lattice_step != step) continue;
      ASSERT_EQ(r.plan_step, step);
      const Plan fine = onCellSteps(r.plan, stepOf(step));
      const ValidationResult v = validatePlan(world.map, world.instance, fine, stepOf(1));
      EXPECT_TRUE(v.valid()) << "seed " << seed << " step " << step << ": " << v.violation.message;
      for (std::size_t i = 0; i < fine.paths.size(); ++i) {
        const Path& p = r.plan.paths[i];
        for (std::size_t t = 0; t + 1 < p.size(); ++t) EXPECT_EQ(fine.paths[i][step * t], p[t]);
        EXPECT_EQ(fine.paths[i].back(), p.back());
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 10);  // of 18
}

TEST(CellSteps, TheFacadeReturnsCellStepsRetimedAndNoDearerAtTheSameSpeed) {
  int fleets = 0, cheaper = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    RandomWorld world(6, seed);
    world.instance.robots[0].start_yaw = 0.4;  // turns from and to yaws are steps too
    world.instance.robots[1].target_yaw = -2.0;
    const int step = 3;
    PlanningOptions on_lattice = onLattice(step);
    on_lattice.cell_steps = false;
    const PlanningResult coarse = planFleet(world.map, world.instance, on_lattice);
    const PlanningResult fine = planFleet(world.map, world.instance, onLattice(step));
    ASSERT_EQ(coarse.status, fine.status) << "seed " << seed;
    if (!fine.success() || fine.lattice_step != step) continue;
    ++fleets;
    EXPECT_EQ(fine.plan_step, 1);
    EXPECT_TRUE(validOnCells(world.map, world.instance, fine)) << "seed " << seed;
    for (const Path& p : fine.plan.paths) {
      for (std::size_t t = 0; t + 1 < p.size(); ++t) EXPECT_LE(moveLength(p[t], p[t + 1]), 1);
    }
    // The same lattice plan: at the same speed (a lattice step lasts `step` cell steps) its
    // cost is never more, and waits and turns retimed to one step make it less.
    EXPECT_LE(fine.metrics.soc, step * coarse.metrics.soc) << "seed " << seed;
    EXPECT_LE(fine.metrics.makespan, step * coarse.metrics.makespan) << "seed " << seed;
    if (fine.metrics.soc < step * coarse.metrics.soc) ++cheaper;
    EXPECT_GT(fine.cell_steps_saved, 0) << "seed " << seed;
    // Same input, same plan.
    EXPECT_EQ(planFleet(world.map, world.instance, onLattice(step)).plan.paths, fine.plan.paths);
  }
  EXPECT_GE(fleets, 3);
  EXPECT_EQ(cheaper, fleets);
}

}  // namespace
}  // namespace fleet_planner::test
