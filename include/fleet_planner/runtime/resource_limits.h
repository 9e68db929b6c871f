#pragma once
/// Limits on what planning may take: map size, fleet size and memory. The map loaders check the
/// size in a map's header before allocating its grid, FleetGraphs checks the fleet and an
/// estimate of its state graphs' memory before building them, and a search checks its distance
/// tables before allocating them; a MemoryGuard on the deadline (memory_guard.h) watches the
/// process's resident memory while the searches run. An instance too large for the machine is
/// thus refused with an error that names the limit, instead of the process being killed by the
/// kernel's out-of-memory killer.
#include <cstddef>
#include <string>

#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

struct ResourceLimits {
  long long max_map_cells = 16'000'000;  ///< width * height of a map
  int max_robots = 1000;                 ///< robots of one instance (one planning call)
  double max_memory_mb = 4096;           ///< the process's resident memory while planning, in MB
};

/// An input over a resource limit. what() names the parameter as "<parameter>=<value>" (for
/// example "max_memory_mb=4096"), what needs more, and by how much.
class ResourceLimitError : public InputError {
 public:
  ResourceLimitError(std::string parameter, const std::string& message)
      : InputError(message), parameter_(std::move(parameter)) {}
  /// "max_map_cells", "max_robots" or "max_memory_mb".
  const std::string& parameter() const { return parameter_; }

 private:
  std::string parameter_;
};

/// Empty when every limit is positive (and finite); otherwise the problem, naming the parameter.
std::string resourceLimitsProblem(const ResourceLimits& limits);

/// Throws ResourceLimitError (max_map_cells) if a map of width x height cells is larger than
/// the limit; `what` names the map in the message. Call it before allocating the grid.
void checkMapCells(long long width, long long height, const ResourceLimits& limits,
                   const std::string& what);

/// Throws ResourceLimitError (max_robots) if `robots` is more than the limit.
void checkRobotCount(long long robots, const ResourceLimits& limits);

/// Memory that planning allocates in proportion to the map, from the sizes of the actual data
/// structures: the grid and its ObstacleIndex (1 + 8 + 4 bytes per cell), one StateGraph per
/// distinct discretised footprint (1 byte per state id, 4 state ids per cell: the state's
/// validity and its edges are bits of that byte), and one distance table per searched agent
/// (a 4-byte distance per state id, SearchSpace).
struct MemoryEstimate {
  int width = 0, height = 0;
  int robots = 0;           ///< robots whose graphs are counted
  int graphs = 0;           ///< distinct state graphs among them
  int searched_agents = 0;  ///< agents whose distance tables are counted
  double map_mb = 0, graphs_mb = 0, search_mb = 0;
  double totalMb() const { return map_mb + graphs_mb + search_mb; }
  /// "61.0 MB (map 12.4 MB, 3 state graphs 24.4 MB, distance tables of 2 agents 24.4 MB)".
  std::string describe() const;
};

/// The estimate for a width x height map, `robots` robots with `graphs` distinct state graphs
/// and `searched_agents` distance tables (0: graphs only).
MemoryEstimate estimateMemory(int width, int height, int robots, int graphs, int searched_agents);

/// Bytes of one StateGraph and of one distance table on a map of `cells` cells.
std::size_t stateGraphBytes(long long cells);
std::size_t distanceTableBytes(long long cells);

/// Throws ResourceLimitError (max_memory_mb) if `in_use_mb` (the process's resident memory now,
/// or 0) plus the estimate exceeds the limit; `what` says what the memory is for.
void checkMemory(const MemoryEstimate& estimate, double in_use_mb, const ResourceLimits& limits,
                 const std::string& what);

/// The process's resident memory (VmRSS) in MB, from /proc/self/statm (one small read, a few
/// microseconds); -1 where /proc is missing.
double residentMemoryMb();

}  // namespace fleet_planner
