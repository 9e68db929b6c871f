#include "fleet_planner/solvers/registry.h"

#include <map>
#include <mutex>

#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

namespace {

std::map<std::string, SolverFactory>& factories() {
  static std::map<std::string, SolverFactory> map;
  return map;
}

std::mutex& registryMutex() {
  static std::mutex m;
  return m;
}

}  // namespace

bool registerSolver(const std::string& name, SolverFactory factory) {
  std::lock_guard<std::mutex> lock(registryMutex());
  factories()[name] = std::move(factory);
  return true;
}

std::unique_ptr<Solver> makeSolver(const std::string& name) {
  SolverFactory factory;
  {
    std::lock_guard<std::mutex> lock(registryMutex());
    auto it = factories().find(name);
    if (it != factories().end()) factory = it->second;
  }
  if (!factory) {
    std::string known;
    for (const auto& n : solverNames()) known += (known.empty() ? "" : ", ") + n;
    throw InvalidInput("unknown backend '" + name + "' (known: " + known + ")");
  }
  return factory();
}

std::unique_ptr<Solver> makeSolver(const std::string& name, const BackendParameters& parameters) {
  std::unique_ptr<Solver> solver = makeSolver(name);
  auto it = parameters.find(name);
  if (it == parameters.end()) it = parameters.find(solver->name());
  if (it != parameters.end()) solver->configure(it->second);
  return solver;
}

std::vector<std::string> checkBackendParameters(const BackendParameters& parameters) {
  std::vector<std::string> problems;
  for (const auto& [backend, values] : parameters) {
    try {
      makeSolver(backend)->configure(values);
    } catch (const std::exception& e) {
      problems.push_back(e.what());
    }
  }
  return problems;
}

std::vector<std::string> solverNames() {
  std::lock_guard<std::mutex> lock(registryMutex());
  std::vector<std::string> names;
  for (const auto& [name, f] : factories()) names.push_back(name);
  return names;
}

const char* statusName(SolveStatus status) {
  switch (status) {
    case SolveStatus::Success:
      return "SUCCESS";
    case SolveStatus::Timeout:
      return "TIMEOUT";
    case SolveStatus::Infeasible:
      return "INFEASIBLE";
    case SolveStatus::Cancelled:
      return "CANCELLED";
    case SolveStatus::InvalidInput:
      return "INVALID_INPUT";
    case SolveStatus::ResourceLimit:
      return "RESOURCE_LIMIT";
    case SolveStatus::InternalError:
      return "INTERNAL_ERROR";
  }
  return "?";
}

}  // namespace fleet_planner
