#pragma once
/// Helpers for the solver tests: build robots, instances and fleet graphs on small maps, run a
/// backend from the registry on a subproblem, turn its paths (Subproblem::robots order) into a
/// plan in instance order, and check that plan with the independent plan validator.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"
#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/runtime/random.h"
#include "fleet_planner/solvers/search/agent_conflicts.h"
#include "fleet_planner/solvers/search/search_space.h"
#include "fleet_planner/solvers/search/soft_path_table.h"
#include "fleet_planner/solvers/solver.h"

#include "test_robots.h"

namespace fleet_planner::test {

/// A two-cell robot: block [-0.5, 1.5] x [-0.5, 0.5], covering its cell and the one ahead.
Robot bar(const std::string& id, GridPose start, GridPose target);
/// A seven-cell triangle polygon (nose at +1 forward, base at -1): its cell, the ones ahead,
/// behind and to the sides, and the two rear corners.
Robot triangle(const std::string& id, GridPose start, GridPose target);
/// An instance of `robots`, in this order.
Instance makeInstance(std::vector<Robot> robots);

/// A map, an instance on it and the fleet's state graphs, kept together because a Subproblem
/// points into them; neither copyable nor movable. The constructor runs validateInstance(), so
/// a malformed scenario (a test bug) throws InvalidInput instead of reaching a solver.
struct World {
  World(GridMap map, std::vector<Robot> robots);
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  GridMap map;
  Instance instance;
  std::unique_ptr<FleetGraphs> graphs;

  /// The targets, in instance order (for planMetrics).
  std::vector<GridPose> targets() const;
  /// Index of the robot with this id; throws std::out_of_range if there is none.
  int robotIndex(const std::string& id) const;
};

/// A map of the paper's benchmark (`../shared/benchmark/maps/<name>.map`, next to the
/// repository), or none when that folder is not there.
std::optional<GridMap> sharedBenchmarkMap(const std::string& name);

/// A subproblem over every robot of `world` in instance order, with no static or moving
/// obstacles, a deadline `time_limit_s` seconds from now and `seed`.
Subproblem allRobots(const World& world, double time_limit_s = 10.0, std::uint64_t seed = 1);

/// `count` robots of the paper's generator on `map` (30 % of them polygons), drawn with `seed`.
std::vector<Robot> generatedRobots(const GridMap& map, int count, std::uint64_t seed);

/// A random walk of `steps` steps of agent a from its start (waits included), on moves the
/// space allows.
StatePath randomWalk(const SearchSpace& space, int a, int steps, Rng& rng);

/// Every pair (a, b), a < b, of the `n` agents of `table` that SoftPathTable::partners gives.
std::vector<std::pair<int, int>> partnerPairs(const SoftPathTable& table, int n);

/// What one solve produced.
struct Outcome {
  SolveResult result;
  double wall_s = 0.0;          ///< wall time of the solve() call (steady_clock)
  Instance planned;             ///< the subproblem's robots, in instance order
  Plan plan;                    ///< their paths in instance order (empty if the paths do not fit)
  std::string shape_problem;    ///< why the paths could not be placed, if they could not
  ValidationResult validation;  ///< validatePlan(map, planned, plan), run on success only
  long long soc = -1;           ///< planMetrics of the plan, on success with a valid plan
};

/// Maps `paths` (one per Subproblem::robots entry, same order) to a plan over `planned` (the
/// subproblem's robots in instance order; a robot of Subproblem::returning starts and ends at its
/// pose there). Returns the problem (wrong count, duplicate or
/// out-of-range robot index) or an empty string.
std::string toInstanceOrder(const World& world, const Subproblem& sub,
                            const std::vector<Path>& paths, Instance& planned, Plan& plan);

/// The validator's verdict on state paths of `sub`'s robots, one per Subproblem::robots entry
/// (returning robots from and back to their poses); a test failure if they do not fit.
ValidationResult validateStatePaths(const World& world, const Subproblem& sub, const SearchSpace& space,
                                    const std::vector<StatePath>& paths);

/// Runs `solver.solve(sub)` timed with steady_clock; on success converts the paths and
/// validates the plan.
Outcome solveWith(Solver& solver, const World& world, const Subproblem& sub);
/// Same with a fresh `makeSolver(name)`.
Outcome solveWith(const std::string& name, const World& world, const Subproblem& sub);

/// One line for failure messages: status name, reason, path count, wall time, validation.
std::string describe(const Outcome& outcome);

/// Success, paths that fit the subproblem and a plan the validator accepts; otherwise a
/// failure naming the status (statusName), the solver's reason and the first violation.
::testing::AssertionResult solvedValidly(const Outcome& outcome);

/// The first step at which a planned robot's footprint overlaps a StaticFootprint of `sub`, or
/// its swept cells overlap it (the static robot "waits" in place), as a message; empty if none.
std::string staticFootprintClash(const World& world, const Subproblem& sub, const Outcome& outcome);

}  // namespace fleet_planner::test
