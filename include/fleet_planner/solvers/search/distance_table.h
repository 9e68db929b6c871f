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
  /// Filled by a breadth-first search instead: reset() makes every one of `states` states
  /// unreachable, set() gives one state its distance, in the search's order (never smaller than
  /// one given before). Two bytes a state until a distance reaches 65,535, then four.
  void reset(std::size_t states);
  void set(StateId s, int steps) {
    if (!narrow_.empty() && steps < kUnreachable) {
      narrow_[s] = static_cast<std::uint16_t>(steps);
      return;
    }
    if (!narrow_.empty()) widen();
    wide_[s] = steps;
  }
  bool reached(StateId s) const { return narrow_.empty() ? wide_[s] >= 0 : narrow_[s] != kUnreachable; }
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
  void widen();
  std::vector<std::uint16_t> narrow_;  // used when every distance is below kUnreachable
  std::vector<std::int32_t> wide_;     // otherwise
};

}  // namespace fleet_planner
