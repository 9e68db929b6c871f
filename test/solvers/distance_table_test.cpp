// Distance tables (distance_table.h): 2-byte storage gives back every distance it was given.
#include "fleet_planner/solvers/search/distance_table.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace fleet_planner {
namespace {

void expectSame(const DistanceTable& table, const std::vector<std::int32_t>& steps) {
  for (std::size_t s = 0; s < steps.size(); ++s)
    ASSERT_EQ(table[static_cast<StateId>(s)], steps[s]) << "state " << s;
}

TEST(DistanceTable, ShortDistancesTakeTwoBytesAndComeBackExactly) {
  const std::vector<std::int32_t> steps{0, 1, -1, 7, 65534, -1, 300};
  DistanceTable table;
  table.assign(steps);
  EXPECT_EQ(table.bytesPerState(), 2);
  expectSame(table, steps);
}

TEST(DistanceTable, ADistanceOf65535StepsOrMoreTakesFourBytes) {
  const std::vector<std::int32_t> steps{0, -1, 65535, 70000, 12};
  DistanceTable table;
  table.assign(steps);
  EXPECT_EQ(table.bytesPerState(), 4);
  expectSame(table, steps);
  // Assigned again with short distances, it goes back to two bytes.
  const std::vector<std::int32_t> short_steps{3, 2, 1, 0, -1};
  table.assign(short_steps);
  EXPECT_EQ(table.bytesPerState(), 2);
  expectSame(table, short_steps);
}

}  // namespace
}  // namespace fleet_planner
