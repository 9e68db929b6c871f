#pragma once
/// Backends by name. Each backend registers a factory in its own source file, so adding one
/// touches no other backend and no caller.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

using SolverFactory = std::function<std::unique_ptr<Solver>()>;

/// Registers `factory` under `name` (returns true, for static registration). Re-registering a
/// name replaces the factory.
bool registerSolver(const std::string& name, SolverFactory factory);

/// A new solver of that name; throws InvalidInput listing the known names if there is none.
std::unique_ptr<Solver> makeSolver(const std::string& name);

/// A new solver of that name configured with `parameters[name]` (or, for a plugin registered as
/// "package/name", `parameters[name()]`) when there are any; throws InvalidInput for an unknown
/// name or option (Solver::configure).
std::unique_ptr<Solver> makeSolver(const std::string& name, const BackendParameters& parameters);

/// Every problem with `parameters`, one line each: a backend that is not registered, an option it
/// does not know, a value out of range. Empty when every entry configures its backend.
std::vector<std::string> checkBackendParameters(const BackendParameters& parameters);

/// Registered names, sorted.
std::vector<std::string> solverNames();

}  // namespace fleet_planner
