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

const std::string kRealMaps = std::string(FLEET_PLANNER_TEST_DATA) + "/../../../shared/realmaps";

// The robots' own poses and yaws of `realmap_scenario.py --robots 50 --seed 3` on the bookstore.
Robot mir100_33() {
  return withYaws(makeRobot("mir100_33", Footprint::block(-8.9, -5.8, 8.9, 5.8), {176, 239, 3}, {121, 240, 2}),
                  -1.905453, 1.771891);
}
Robot fetch_44() {
  return withYaws(makeRobot("fetch_44", Footprint::circle(6.0), {156, 241, 2}, {175, 235, 3}), 1.896193, -1.200034);
}
Robot mir100_45() {
  return withYaws(makeRobot("mir100_45", Footprint::block(-8.9, -5.8, 8.9, 5.8), {132, 242, 3}, {147, 239, 0}),
                  -1.497010, -0.132633);
}

// The pair planned raw as the node plans (backward moves, the default lattice), checked by
// the validator.
void expectPlanned(const std::vector<Robot>& robots) {
  const GridMap map = loadMap(kRealMaps + "/bookstore.yaml");
  Instance instance;
  instance.robots = robots;
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

// In the 1.5 m aisle between two shelves, the MiR100 (0.9 x 0.6 m) drives west out of the place
// the Fetch (0.6 m across) comes east to. LA-LNS's repairs, ordered and pocket repairs and
// LA-CBS found no plan for the pair in 30 s; LA-LaCAM on the pair alone finds one in 1,709
// configurations.
TEST(Knots, AMir100AndAFetchInABookstoreAisle) {
  if (!std::filesystem::exists(kRealMaps + "/bookstore.yaml")) GTEST_SKIP() << "no " << kRealMaps;
  expectPlanned({mir100_33(), fetch_44()});
}

// Two MiR100s in the same aisle, too narrow for them to pass side by side: both leave it by its
// east end, where one waits beside the other's way while that one passes, and they drive back
// in one after the other. The pocket repair finds it once its budget has doubled twice for the
// pair (LA-LaCAM alone needs 447,000 configurations).
TEST(Knots, TwoMir100sInABookstoreAisle) {
  if (!std::filesystem::exists(kRealMaps + "/bookstore.yaml")) GTEST_SKIP() << "no " << kRealMaps;
  expectPlanned({mir100_33(), mir100_45()});
}

}  // namespace
}  // namespace fleet_planner::test
