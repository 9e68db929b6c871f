#include "fleet_planner/runtime/resource_limits.h"

#include <unistd.h>

#include <cmath>
#include <cstdint>

#include "number_format.h"

namespace fleet_planner {

namespace {

constexpr double kMb = 1048576.0;

}  // namespace

std::string resourceLimitsProblem(const ResourceLimits& limits) {
  if (limits.max_map_cells < 1)
    return "max_map_cells must be >= 1 (got " + std::to_string(limits.max_map_cells) + ")";
  if (limits.max_robots < 1)
    return "max_robots must be >= 1 (got " + std::to_string(limits.max_robots) + ")";
  if (!(limits.max_memory_mb > 0) || !std::isfinite(limits.max_memory_mb)) {
    return "max_memory_mb must be > 0 and finite (got " + io::formatNumber(limits.max_memory_mb) + ")";
  }
  return "";
}

void checkMapCells(long long width, long long height, const ResourceLimits& limits,
                   const std::string& what) {
  const long long cells = width * height;
  if (cells <= limits.max_map_cells) return;
  throw ResourceLimitError(
      "max_map_cells", what + ": map of " + std::to_string(width) + " x " + std::to_string(height) +
                           " = " + std::to_string(cells) +
                           " cells exceeds max_map_cells=" + std::to_string(limits.max_map_cells));
}

void checkRobotCount(long long robots, const ResourceLimits& limits) {
  if (robots <= limits.max_robots) return;
  throw ResourceLimitError("max_robots", std::to_string(robots) + " robots exceed max_robots=" +
                                             std::to_string(limits.max_robots));
}

std::size_t stateGraphBytes(long long cells) {
  return static_cast<std::size_t>(cells) * 4 * sizeof(std::uint8_t);  // StateGraph::flags_
}

std::size_t distanceTableBytes(long long cells) {
  // SearchSpace::distances_: 2 bytes a state while distances stay below 65,535 steps.
  return static_cast<std::size_t>(cells) * 4 * sizeof(std::uint16_t);
}

MemoryEstimate estimateMemory(int width, int height, int robots, int graphs, int searched_agents) {
  MemoryEstimate e;
  e.width = width;
  e.height = height;
  e.robots = robots;
  e.graphs = graphs;
  e.searched_agents = searched_agents;
  const long long cells = static_cast<long long>(width) * height;
  // GridMap (1 byte), ObstacleIndex clearance (8 bytes) and row prefix counts (4 bytes) per cell.
  e.map_mb = static_cast<double>(cells) *
             (sizeof(std::uint8_t) + sizeof(std::int64_t) + sizeof(std::int32_t)) / kMb;
  e.graphs_mb = static_cast<double>(graphs) * static_cast<double>(stateGraphBytes(cells)) / kMb;
  e.search_mb =
      static_cast<double>(searched_agents) * static_cast<double>(distanceTableBytes(cells)) / kMb;
  return e;
}

std::string MemoryEstimate::describe() const {
  std::string out = io::formatMb(totalMb()) + " (map " + io::formatMb(map_mb) + ", " + std::to_string(graphs) +
                    " state graph" + (graphs == 1 ? "" : "s") + " " + io::formatMb(graphs_mb);
  if (searched_agents > 0) {
    out += ", distance tables of " + std::to_string(searched_agents) + " agent" +
           (searched_agents == 1 ? "" : "s") + " " + io::formatMb(search_mb);
  }
  return out + ")";
}

void checkMemory(const MemoryEstimate& estimate, double in_use_mb, const ResourceLimits& limits,
                 const std::string& what) {
  const double in_use = in_use_mb > 0 ? in_use_mb : 0.0;
  if (in_use + estimate.totalMb() <= limits.max_memory_mb) return;
  throw ResourceLimitError("max_memory_mb",
                           what + " on a " + std::to_string(estimate.width) + " x " +
                               std::to_string(estimate.height) + " map need an estimated " +
                               estimate.describe() +
                               (in_use > 0 ? " on top of the " + io::formatMb(in_use) + " in use" : "") +
                               ", more than max_memory_mb=" + io::formatNumber(limits.max_memory_mb));
}

double residentMemoryMb() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (f == nullptr) return -1.0;
  long long size = 0, resident = 0;
  const int read = std::fscanf(f, "%lld %lld", &size, &resident);
  std::fclose(f);
  if (read != 2) return -1.0;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / kMb;
}

}  // namespace fleet_planner
