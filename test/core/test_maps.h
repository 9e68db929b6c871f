#pragma once
// Small maps drawn as text for the tests: '.' free, '@' blocked; the first string is row y = 0.
#include <string>
#include <vector>

#include "fleet_planner/model/grid_map.h"

namespace fleet_planner::test {

inline GridMap mapFromRows(const std::vector<std::string>& rows) {
  std::vector<std::uint8_t> cells;
  for (const auto& row : rows)
    for (char c : row) cells.push_back(c == '@' ? 1 : 0);
  return GridMap(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()), cells);
}

inline GridMap freeMap(int width, int height) {
  return mapFromRows(std::vector<std::string>(height, std::string(width, '.')));
}

}  // namespace fleet_planner::test
