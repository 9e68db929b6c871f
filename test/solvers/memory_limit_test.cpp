// The memory limit in the searches: with a memory guard on the deadline, every backend stops
// with RESOURCE_LIMIT and a reason naming max_memory_mb, instead of growing until the process
// is killed; the layered planner reports the same.
#include <gtest/gtest.h>

#include "fleet_planner/runtime/memory_guard.h"
#include "fleet_planner/runtime/resource_limits.h"
#include "fleet_planner/layered/layered_planner.h"
#include "fleet_planner/solvers/registry.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Two one-cell robots that must swap in a closed corridor (row 0, cut off by the wall in row 1)
// can never pass each other, while six more roam a 20 x 10 room: LA-LaCAM cannot prove that
// before the end of time and keeps adding configurations, so its memory grows without bound.
GridMap corridorAndRoom() {
  std::vector<std::string> rows(12, std::string(20, '.'));
  rows[0] = "......@@@@@@@@@@@@@@";
  rows[1] = std::string(20, '@');
  return mapFromRows(rows);
}

std::vector<Robot> swapInCorridorAndRoamers() {
  std::vector<Robot> robots{dot("a", {0, 0, 0}, {5, 0, 0}), dot("b", {5, 0, 1}, {0, 0, 1})};
  for (int i = 0; i < 6; ++i) {
    robots.push_back(dot("r" + std::to_string(i), {1 + 3 * i, 2, 2}, {18 - 3 * i, 11, 3}));
  }
  return robots;
}

TEST(MemoryLimit, AGrowingLaLacamSearchStopsAtTheLimit) {
  const World world(corridorAndRoom(), swapInCorridorAndRoamers());
  const MemoryGuard guard(residentMemoryMb() + 40);
  Subproblem sub = allRobots(world, 30.0);
  sub.deadline = sub.deadline.withMemoryGuard(&guard);
  const Outcome out = solveWith("la_lacam", world, sub);
  EXPECT_EQ(out.result.status, SolveStatus::ResourceLimit) << describe(out);
  EXPECT_TRUE(contains(out.result.reason, "max_memory_mb=")) << out.result.reason;
  EXPECT_LT(out.wall_s, 20.0) << "stopped by its memory, long before the time limit";
  EXPECT_GT(out.result.stats.high_level_nodes, 1000) << "the search ran until the limit";
}

TEST(MemoryLimit, EveryBackendReportsTheLimitOnceTheGuardHasTripped) {
  const World world(corridorAndRoom(), swapInCorridorAndRoamers());
  const MemoryGuard tight(1.0);  // below any process: trips at the first check
  for (const std::string& name : solverNames()) {
    Subproblem sub = allRobots(world, 30.0);
    sub.deadline = sub.deadline.withMemoryGuard(&tight);
    const Outcome out = solveWith(name, world, sub);
    EXPECT_EQ(out.result.status, SolveStatus::ResourceLimit) << name << ": " << describe(out);
    EXPECT_TRUE(contains(out.result.reason, "max_memory_mb=1"))
        << name << ": " << out.result.reason;
  }
}

TEST(MemoryLimit, DistanceTablesThatWouldNotFitAreRefusedBeforeAllocation) {
  // 600 x 600 cells: 2.75 MB of distances per robot (2 bytes a state), 44 MB for sixteen,
  // against 20 MB of room.
  std::vector<Robot> robots;
  for (int i = 0; i < 16; ++i)
    robots.push_back(dot("d" + std::to_string(i), {10 * i, 0, 0}, {10 * i, 599, 2}));
  const World world(freeMap(600, 600), robots);
  const MemoryGuard guard(residentMemoryMb() + 20);
  for (const std::string& name : solverNames()) {
    Subproblem sub = allRobots(world, 30.0);
    sub.deadline = sub.deadline.withMemoryGuard(&guard);
    const Outcome out = solveWith(name, world, sub);
    EXPECT_EQ(out.result.status, SolveStatus::ResourceLimit) << name << ": " << describe(out);
    EXPECT_TRUE(contains(out.result.reason, "distance tables of 16 robots")) << out.result.reason;
    EXPECT_TRUE(contains(out.result.reason, "max_memory_mb=")) << out.result.reason;
  }
}

TEST(MemoryLimit, TheLayeredPlannerAnswersResourceLimit) {
  const World world(corridorAndRoom(), swapInCorridorAndRoamers());
  const MemoryGuard tight(1.0);
  for (const char* backend : {"la_cbs", "la_lacam"}) {
    for (const bool layered : {false, true}) {
      LayeredOptions options;
      options.backend = backend;
      options.decompose = layered;
      const LayeredResult r = planLayered(world.map, world.instance, *world.graphs, options,
                                          Deadline::in(30).withMemoryGuard(&tight));
      EXPECT_EQ(r.status, SolveStatus::ResourceLimit)
          << backend << (layered ? " layered: " : " raw: ") << r.reason;
      EXPECT_TRUE(contains(r.reason, "max_memory_mb=1")) << r.reason;
      EXPECT_STREQ(statusName(r.status), "RESOURCE_LIMIT");
    }
  }
}

}  // namespace
}  // namespace fleet_planner::test
