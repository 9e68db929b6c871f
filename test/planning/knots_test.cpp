// Knots of two robots on a real map (the bookstore of ../shared/realmaps, when it is there),
// planned as the node plans them: backward moves allowed, the default lattice, the whole fleet
// as one subproblem.
#include <gtest/gtest.h>

#include <filesystem>

#include "fleet_planner/io/map_io.h"
#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/planning/plan_fleet.h"
#include "test_paths.h"
#include "test_robots.h"

namespace fleet_planner::test {
namespace {

Robot withYaws(Robot r, double start_yaw, double target_yaw) {
  r.start_yaw = start_yaw;
  r.target_yaw = target_yaw;
  return r;
}

// Robots mir100_33 and fetch_44 of `realmap_scenario.py --robots 50 --seed 3` on the
// bookstore: in the 1.5 m aisle between two shelves, the MiR100 (0.9 x 0.6 m) drives west out
// of the place the Fetch (0.6 m across) comes east to. LA-LNS's repairs, ordered and pocket
// repairs and LA-CBS found no plan for the pair in 30 s; LA-LaCAM on the pair alone finds one
// in 1,709 configurations.
TEST(Knots, APairInABookstoreAisle) {
  const std::string root = std::string(FLEET_PLANNER_TEST_DATA) + "/../../../shared/realmaps";
  if (!std::filesystem::exists(root + "/bookstore.yaml")) GTEST_SKIP() << "no " << root;
  const GridMap map = loadMap(root + "/bookstore.yaml");
  Instance instance;
  instance.robots = {
      withYaws(makeRobot("mir100_33", Footprint::block(-8.9, -5.8, 8.9, 5.8), {176, 239, 3}, {121, 240, 2}),
               -1.905453, 1.771891),
      withYaws(makeRobot("fetch_44", Footprint::circle(6.0), {156, 241, 2}, {175, 235, 3}), 1.896193,
               -1.200034)};
  PlanningOptions o;
  o.model.allow_backward = true;
  o.decompose = false;
  o.threads = 1;
  o.time_limit = 30.0;
  const PlanningResult r = planFleet(map, instance, o);
  ASSERT_TRUE(r.success()) << statusName(r.status) << ": " << r.reason;
  ActionModel model;
  model.allow_backward = true;
  model.step = r.lattice_step;
  const ValidationResult valid = validatePlan(map, instance, r.plan, model);
  EXPECT_TRUE(valid.valid()) << valid.violation.message;
}

}  // namespace
}  // namespace fleet_planner::test
