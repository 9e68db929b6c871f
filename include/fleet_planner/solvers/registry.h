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

/// Registered names, sorted.
std::vector<std::string> solverNames();

}  // namespace fleet_planner
