// Checks of the planning options; see planning_options.h.
#include "fleet_planner/planning/planning_options.h"

#include <algorithm>
#include <thread>

#include "fleet_planner/planning/lattice.h"
#include "fleet_planner/solvers/registry.h"

namespace fleet_planner {

std::vector<std::string> checkPlanningOptions(const PlanningOptions& o) {
  std::vector<std::string> problems;
  auto known = [&](const char* option, const std::string& name) {
    try {
      makeSolver(name);
    } catch (const std::exception& e) {
      problems.push_back(std::string(option) + ": " + e.what());
    }
  };
  known("backend", o.backend);
  if (!o.fallback.empty()) known("fallback", o.fallback);
  for (const std::string& p : checkBackendParameters(o.backend_parameters)) problems.push_back("backend_parameters: " + p);
  if (o.last_step < 1 || o.last_step > 4) problems.push_back("steps: must be 1..4 (got " + std::to_string(o.last_step) + ")");
  if (o.threads < 0) problems.push_back("threads: must be >= 0, 0 for the machine's cores (got " + std::to_string(o.threads) + ")");
  if (o.lattice_step < 0) problems.push_back("lattice_step: must be >= 0 cells, 0 for the default (got " + std::to_string(o.lattice_step) + ")");
  if (!(o.time_limit >= 0)) problems.push_back("time_limit: must be >= 0 seconds");
  return problems;
}

int initialLatticeStep(const PlanningOptions& options, const Instance& instance) {
  return options.lattice_step > 0 ? options.lattice_step : defaultLatticeStep(instance);
}

int effectiveThreads(const PlanningOptions& options) {
  if (options.threads > 0) return options.threads;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace fleet_planner
