#pragma once
/// One agent's steps to its target from every state of its graph (the low-level heuristic of
/// search_space.h). It takes 2 bytes a state while every distance is below 65,535 steps, as on
/// every map of the benchmark, and 4 bytes otherwise: a fleet of 500 robots on a 256 x 256 map
/// holds half the memory it held in 4-byte tables.
#include <cstdint>
#include <vector>

#include "fleet_planner/model/state_graph.h"

namespace fleet_planner {

class DistanceTable {
 public:
  /// Takes a copy of `steps` (indexed by state id; -1 where the target is unreachable).
  void assign(const std::vector<std::int32_t>& steps);
  /// Steps from s to the target; -1 if unreachable.
  int operator[](StateId s) const {
    if (narrow_.empty()) return wide_[s];
    const std::uint16_t d = narrow_[s];
    return d == kUnreachable ? -1 : d;
  }
  /// Bytes a state in this table.
  int bytesPerState() const { return narrow_.empty() && !wide_.empty() ? 4 : 2; }

 private:
  static constexpr std::uint16_t kUnreachable = 0xFFFF;
  std::vector<std::uint16_t> narrow_;  // used when every distance is below kUnreachable
  std::vector<std::int32_t> wide_;     // otherwise
};

}  // namespace fleet_planner
