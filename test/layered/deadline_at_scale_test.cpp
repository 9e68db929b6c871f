// Deadlines on large instances (found by `fleet_planner_cli stress --min-side 200 --max-side 256
// --min-agents 40 --max-agents 80 --time-limit 0.1`): the work done once per call in proportion
// to map x robots (the solvability pre-check, the relation graphs, the backends' distance
// tables, the state graphs) used to ignore the deadline, and a 0.1 s call took 0.2-0.5 s of CPU.
// Each now checks it. The assertions are on the calling thread's CPU time, which does not depend
// on how loaded the machine is.
#include <gtest/gtest.h>
#include <time.h>

#include "fleet_planner/model/instance_check.h"
#include "fleet_planner/io/instance_generator.h"
#include "fleet_planner/layered/layered_planner.h"
#include "fleet_planner/solvers/registry.h"
#include "test_maps.h"
#include "test_robots.h"

namespace fleet_planner {
namespace {

double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// 400 x 400 cells with a few walls and 60 robots of mixed footprints: every per-robot table is
// 640,000 states, so that each phase costs tens of milliseconds per robot.
struct Large {
  Large() : map(makeMap()) {
    GeneratorOptions g;
    g.robots = 60;
    g.seed = 11;
    g.polygon_share = 0.5;
    instance = generateInstance(map, g);
    graphs = std::make_unique<FleetGraphs>(map, test::footprintsOf(instance));
  }
  static GridMap makeMap() {
    std::vector<std::string> rows(400, std::string(400, '.'));
    for (int y = 0; y < 380; ++y) rows[y][100] = rows[399 - y][300] = '@';
    return test::mapFromRows(rows);
  }
  GridMap map;
  Instance instance;
  std::unique_ptr<FleetGraphs> graphs;
};

const Large& large() {
  static const Large l;
  return l;
}

// CPU seconds past the limit. The unfixed code took 1.0-1.7 s here; 0.1 s is the bound of a
// release build, and sanitizer builds (scripts/sanitize) run several times slower.
#if defined(__SANITIZE_ADDRESS__)
constexpr double kLimit = 0.05, kBound = 0.4;
#else
constexpr double kLimit = 0.05, kBound = 0.1;
#endif

TEST(DeadlineAtScale, LayeredAndRawCallsStopWithinTheBound) {
  const Large& l = large();
  for (const std::string& backend : solverNames()) {
    for (const bool layered : {false, true}) {
      LayeredOptions o;
      o.backend = backend;
      o.decompose = layered;
      const double cpu0 = threadCpuSeconds();
      const LayeredResult r = planLayered(l.map, l.instance, *l.graphs, o, Deadline::in(kLimit));
      const double cpu = threadCpuSeconds() - cpu0;
      EXPECT_EQ(r.status, SolveStatus::Timeout)
          << backend << (layered ? " layered: " : " raw: ") << r.reason;
      EXPECT_LT(cpu, kLimit + kBound)
          << backend << (layered ? " layered" : " raw") << ": " << r.reason;
    }
  }
}

TEST(DeadlineAtScale, SolvabilityPreCheckStopsAtTheDeadline) {
  const Large& l = large();
  const double cpu0 = threadCpuSeconds();
  const SolvabilityReport expired = checkSolvability(l.instance, *l.graphs, Deadline::in(0));
  EXPECT_LT(threadCpuSeconds() - cpu0, 0.01);
  EXPECT_FALSE(expired.complete);
  EXPECT_TRUE(expired.problems.empty());
  const SolvabilityReport full = checkSolvability(l.instance, *l.graphs);
  EXPECT_TRUE(full.complete);
  EXPECT_TRUE(full.solvable()) << full.summary();
}

TEST(DeadlineAtScale, StateGraphsStopAtTheDeadline) {
  const Large& l = large();
  const double cpu0 = threadCpuSeconds();
  try {
    FleetGraphs(l.map, test::footprintsOf(l.instance), {}, 1, {}, Deadline::in(0));
    ADD_FAILURE() << "expected DeadlineExpired";
  } catch (const DeadlineExpired& e) {
    EXPECT_NE(std::string(e.what()).find("state graphs"), std::string::npos) << e.what();
  }
  EXPECT_LT(threadCpuSeconds() - cpu0, kBound);
}

}  // namespace
}  // namespace fleet_planner
