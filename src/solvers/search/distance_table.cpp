#include "fleet_planner/solvers/search/distance_table.h"

#include <algorithm>

namespace fleet_planner {

void DistanceTable::assign(const std::vector<std::int32_t>& steps) {
  const std::int32_t longest = steps.empty() ? -1 : *std::max_element(steps.begin(), steps.end());
  if (longest < kUnreachable) {
    std::vector<std::int32_t>().swap(wide_);
    narrow_.resize(steps.size());
    for (std::size_t s = 0; s < steps.size(); ++s)
      narrow_[s] = steps[s] < 0 ? kUnreachable : static_cast<std::uint16_t>(steps[s]);
  } else {
    std::vector<std::uint16_t>().swap(narrow_);
    wide_ = steps;
  }
}

void DistanceTable::reset(std::size_t states) {
  std::vector<std::int32_t>().swap(wide_);
  narrow_.assign(states, kUnreachable);
}

void DistanceTable::widen() {
  wide_.assign(narrow_.size(), -1);
  for (std::size_t s = 0; s < narrow_.size(); ++s) {
    if (narrow_[s] != kUnreachable) wide_[s] = narrow_[s];
  }
  std::vector<std::uint16_t>().swap(narrow_);
}

}  // namespace fleet_planner
