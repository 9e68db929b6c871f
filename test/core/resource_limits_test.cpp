// Resource limits: maps, fleets and state graphs over a limit are refused before they are
// allocated, with an error naming the limit; the memory guard stops deadlines.
#include "fleet_planner/runtime/resource_limits.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <sstream>
#include <thread>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/io/map_io.h"
#include "fleet_planner/runtime/memory_guard.h"
#include "test_maps.h"
#include "test_paths.h"

namespace fleet_planner {
namespace {

using test::dataPath;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// Runs `f`, expects a ResourceLimitError for `parameter` whose message contains every part.
template <class F>
void expectLimit(F&& f, const std::string& parameter, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "expected a ResourceLimitError for " << parameter;
  } catch (const ResourceLimitError& e) {
    EXPECT_EQ(e.parameter(), parameter) << e.what();
    for (const auto& part : parts)
      EXPECT_TRUE(contains(e.what(), part)) << e.what() << "\n  lacks: " << part;
  }
}

TEST(ResourceLimits, DefaultsAreSaneAndUsable) {
  const ResourceLimits limits;
  EXPECT_EQ(limits.max_map_cells, 16'000'000);
  EXPECT_EQ(limits.max_robots, 1000);
  EXPECT_EQ(limits.max_memory_mb, 4096);
  EXPECT_EQ(resourceLimitsProblem(limits), "");
}

TEST(ResourceLimits, EachBadLimitIsNamed) {
  ResourceLimits a, b, c, d;
  a.max_map_cells = 0;
  b.max_robots = -1;
  c.max_memory_mb = 0;
  d.max_memory_mb = NAN;
  EXPECT_EQ(resourceLimitsProblem(a).rfind("max_map_cells", 0), 0u);
  EXPECT_EQ(resourceLimitsProblem(b).rfind("max_robots", 0), 0u);
  EXPECT_EQ(resourceLimitsProblem(c).rfind("max_memory_mb", 0), 0u);
  EXPECT_EQ(resourceLimitsProblem(d).rfind("max_memory_mb", 0), 0u);
}

TEST(ResourceLimits, MapCellsAndRobotCountChecks) {
  ResourceLimits limits;
  limits.max_map_cells = 100;
  limits.max_robots = 3;
  EXPECT_NO_THROW(checkMapCells(10, 10, limits, "m"));
  expectLimit([&] { checkMapCells(10, 11, limits, "warehouse.map"); }, "max_map_cells",
              {"warehouse.map", "10 x 11 = 110 cells", "max_map_cells=100"});
  EXPECT_NO_THROW(checkRobotCount(3, limits));
  expectLimit([&] { checkRobotCount(4, limits); }, "max_robots", {"4 robots", "max_robots=3"});
}

TEST(ResourceLimits, MovingAiHeaderOverTheLimitIsRefusedBeforeTheRows) {
  // The header promises 5000 x 5000 cells (more than the default 16M) and no row follows: the
  // limit, not the missing rows, is the error, so the 25 MB grid was never allocated.
  std::istringstream big("type octile\nheight 5000\nwidth 5000\nmap\n");
  expectLimit([&] { parseMovingAiMap(big, "big.map"); }, "max_map_cells",
              {"big.map", "5000 x 5000 = 25000000 cells", "max_map_cells=16000000"});
  // With a larger limit the same header gets as far as the rows.
  ResourceLimits limits;
  limits.max_map_cells = 30'000'000;
  std::istringstream again("type octile\nheight 5000\nwidth 5000\nmap\n");
  EXPECT_THROW(parseMovingAiMap(again, "big.map", limits), ParseError);
}

TEST(ResourceLimits, MapServerImageOverTheLimitIsRefused) {
  MapServerOptions options;
  options.limits.max_map_cells = 10;  // the image is 4 x 3
  expectLimit([&] { loadMapServerMap(dataPath("map_server_p2.yaml"), options); }, "max_map_cells",
              {"map_server_p2.pgm", "4 x 3 = 12 cells", "max_map_cells=10"});
  options.limits.max_map_cells = 12;
  EXPECT_NO_THROW(loadMapServerMap(dataPath("map_server_p2.yaml"), options));
  options.limits.max_map_cells = 11;  // loadMap passes the limit on too, for either format
  EXPECT_THROW(loadMap(dataPath("map_server_p2.yaml"), options), ResourceLimitError);
}

TEST(ResourceLimits, FleetGraphsRefuseMoreRobotsThanTheLimit) {
  const GridMap map = test::freeMap(10, 10);
  ResourceLimits limits;
  limits.max_robots = 2;
  const std::vector<Footprint> three(3, Footprint::circle(0.4));
  expectLimit([&] { FleetGraphs(map, three, {}, 1, limits); }, "max_robots",
              {"3 robots", "max_robots=2"});
  limits.max_robots = 3;
  EXPECT_NO_THROW(FleetGraphs(map, three, {}, 1, limits));
}

TEST(ResourceLimits, GraphEstimateIsTheMemoryTheGraphsTake) {
  const GridMap map = test::freeMap(37, 23);
  const std::vector<Footprint> fps{Footprint::circle(0.4), Footprint::circle(1.5),
                                   Footprint::block(-1, -0.5, 2, 0.5),
                                   Footprint::circle(0.45)};  // the two small circles share a graph
  const FleetGraphs graphs(map, fps);
  ASSERT_EQ(graphs.numGraphs(), 3);
  const MemoryEstimate e = estimateMemory(map.width(), map.height(), 4, graphs.numGraphs(), 0);
  EXPECT_DOUBLE_EQ(e.graphs_mb * 1048576.0, static_cast<double>(graphs.memoryBytes()));
  EXPECT_EQ(stateGraphBytes(37 * 23), 37u * 23u * 4u);
  EXPECT_EQ(distanceTableBytes(37 * 23), 37u * 23u * 8u);  // 4 headings, 2 bytes
  EXPECT_TRUE(contains(e.describe(), "3 state graphs")) << e.describe();
}

TEST(ResourceLimits, BigFleetIsRefusedWithAClearErrorInsteadOfAllocating) {
  // 16M cells (the largest map the default allows) and 70 robots of different sizes: their
  // state graphs would need about 4.4 GB, more than the default max_memory_mb. FleetGraphs must
  // refuse before building any of them: at once, and without the memory.
  const int side = 4000;
  const GridMap map(side, side,
                    std::vector<std::uint8_t>(static_cast<std::size_t>(side) * side, 0));
  std::vector<Footprint> fps;  // 10 lengths x 7 widths: 70 different cell sets, 70 graphs
  for (int i = 0; i < 70; ++i)
    fps.push_back(Footprint::block(-0.4, -0.4, 0.4 + i % 10, 0.4 + i / 10));
  const double rss_before = residentMemoryMb();
  const auto t0 = std::chrono::steady_clock::now();
  expectLimit([&] { FleetGraphs(map, fps); }, "max_memory_mb",
              {"state graphs of 70 robots", "4000 x 4000 map", "70 state graphs", "estimated",
               "max_memory_mb=4096"});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(seconds, 5.0);  // about 0.1 s; building the graphs would take minutes
  if (rss_before > 0) {
    EXPECT_LT(residentMemoryMb() - rss_before, 200.0);  // not one 64 MB graph per robot
  }
}

TEST(MemoryGuard, TripsOnlyAboveItsLimitAndStaysTripped) {
  const double rss = residentMemoryMb();
  ASSERT_GT(rss, 1.0);
  const MemoryGuard roomy(rss + 10000);
  EXPECT_FALSE(roomy.exceeded());
  const MemoryGuard tight(1.0);
  EXPECT_TRUE(tight.exceeded());
  EXPECT_TRUE(tight.exceeded());
  EXPECT_GT(tight.peakSampledMb(), 1.0);
  EXPECT_TRUE(contains(tight.reason(), "max_memory_mb=1")) << tight.reason();
}

TEST(MemoryGuard, ReserveRefusesAnAllocationThatWouldNotFit) {
  const MemoryGuard guard(residentMemoryMb() + 100);
  EXPECT_NO_THROW(guard.reserve(10, "ten"));
  expectLimit([&] { guard.reserve(1000, "the distance tables of 9 robots"); }, "max_memory_mb",
              {"the distance tables of 9 robots", "1000.0 MB", "max_memory_mb="});
}

TEST(MemoryGuard, ExpiresADeadlineAndTheDeadlinesDerivedFromIt) {
  const MemoryGuard tight(1.0);
  const Deadline plain = Deadline::in(100);
  EXPECT_FALSE(plain.expired());
  EXPECT_FALSE(plain.outOfMemory());
  const Deadline guarded = plain.withMemoryGuard(&tight);
  EXPECT_TRUE(guarded.expired());
  EXPECT_TRUE(guarded.outOfMemory());
  EXPECT_FALSE(guarded.timedOut());
  EXPECT_FALSE(guarded.cancelled());
  EXPECT_TRUE(guarded.within(50).expired());  // a subproblem's share keeps the guard
  EXPECT_EQ(guarded.within(50).memoryGuard(), &tight);
  EXPECT_TRUE(Deadline().withMemoryGuard(&tight).expired());  // no time limit, still guarded
  const MemoryGuard roomy(residentMemoryMb() + 10000);
  EXPECT_FALSE(Deadline().withMemoryGuard(&roomy).expired());
}

}  // namespace
}  // namespace fleet_planner
