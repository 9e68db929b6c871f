#include "solver_test_util.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "fleet_planner/io/instance_generator.h"
#include "fleet_planner/io/map_io.h"
#include "fleet_planner/model/collision.h"
#include "fleet_planner/model/footprint_cells.h"
#include "fleet_planner/model/instance_check.h"
#include "fleet_planner/solvers/registry.h"
#include "fleet_planner/solvers/search/solve_common.h"

namespace fleet_planner::test {

namespace {

}  // namespace

Robot bar(const std::string& id, GridPose start, GridPose target) {
  return makeRobot(id, Footprint::block(-0.5, -0.5, 1.5, 0.5), start, target);
}

Robot triangle(const std::string& id, GridPose start, GridPose target) {
  return makeRobot(id, Footprint::polygon({{1, 0}, {-1, 1}, {-1, -1}}), start, target);
}

Instance makeInstance(std::vector<Robot> robots) {
  Instance instance;
  instance.robots = std::move(robots);
  return instance;
}

World::World(GridMap map_in, std::vector<Robot> robots)
    : map(std::move(map_in)), instance(makeInstance(std::move(robots))) {
  validateInstance(map, instance);
  graphs = std::make_unique<FleetGraphs>(map, footprintsOf(instance));
}

std::vector<GridPose> World::targets() const {
  std::vector<GridPose> out;
  for (const Robot& r : instance.robots) out.push_back(r.target);
  return out;
}

int World::robotIndex(const std::string& id) const {
  for (std::size_t i = 0; i < instance.robots.size(); ++i)
    if (instance.robots[i].id == id) return static_cast<int>(i);
  throw std::out_of_range("no robot '" + id + "'");
}

std::optional<GridMap> sharedBenchmarkMap(const std::string& name) {
  const std::string path = std::string(FLEET_PLANNER_TEST_DATA) + "/../../../shared/benchmark/maps/" + name + ".map";
  if (!std::filesystem::exists(path)) return std::nullopt;
  return loadMovingAiMap(path);
}

Subproblem allRobots(const World& world, double time_limit_s, std::uint64_t seed) {
  Subproblem sub;
  sub.instance = &world.instance;
  sub.graphs = world.graphs.get();
  for (std::size_t i = 0; i < world.instance.robots.size(); ++i)
    sub.robots.push_back(static_cast<int>(i));
  sub.deadline = Deadline::in(time_limit_s);
  sub.seed = seed;
  return sub;
}

std::vector<Robot> generatedRobots(const GridMap& map, int count, std::uint64_t seed) {
  GeneratorOptions o;
  o.robots = count;
  o.seed = seed;
  o.polygon_share = 0.3;
  return generateInstance(map, o).robots;
}

StatePath randomWalk(const SearchSpace& space, int a, int steps, Rng& rng) {
  StatePath path{space.start(a)};
  for (int t = 0; t < steps; ++t) {
    std::vector<StateId> next{path.back()};
    space.graph(a).forEachSuccessor(path.back(), [&](Action act, StateId s) {
      if (space.allows(a, path.back(), act)) next.push_back(s);
    });
    path.push_back(next[rng.uniformInt(0, static_cast<std::int64_t>(next.size()) - 1)]);
  }
  return path;
}

std::vector<std::pair<int, int>> partnerPairs(const SoftPathTable& table, int n) {
  std::vector<std::pair<int, int>> out;
  for (int a = 0; a < n; ++a) {
    for (int b : table.partners(a)) {
      if (a < b) out.emplace_back(a, b);
    }
  }
  return out;
}

std::string toInstanceOrder(const World& world, const Subproblem& sub,
                            const std::vector<Path>& paths, Instance& planned, Plan& plan) {
  planned = Instance{};
  plan = Plan{};
  if (paths.size() != sub.robots.size()) {
    return std::to_string(paths.size()) + " paths for " + std::to_string(sub.robots.size()) +
           " subproblem robots";
  }
  const int n = static_cast<int>(world.instance.robots.size());
  std::vector<int> slot(n, -1);  // instance index -> position in sub.robots
  for (std::size_t k = 0; k < sub.robots.size(); ++k) {
    const int r = sub.robots[k];
    if (r < 0 || r >= n) return "subproblem robot index " + std::to_string(r) + " is out of range";
    if (slot[r] >= 0) return "robot " + std::to_string(r) + " is listed twice";
    slot[r] = static_cast<int>(k);
  }
  for (int r = 0; r < n; ++r) {
    if (slot[r] < 0) continue;
    planned.robots.push_back(world.instance.robots[r]);
    for (const StaticFootprint& back : sub.returning) {  // planned from and back to that pose
      if (back.robot == r) planned.robots.back().start = planned.robots.back().target = back.pose;
    }
    plan.paths.push_back(paths[slot[r]]);
  }
  return "";
}

ValidationResult validateStatePaths(const World& world, const Subproblem& sub, const SearchSpace& space,
                                    const std::vector<StatePath>& paths) {
  Instance planned;
  Plan plan;
  const std::string shape = toInstanceOrder(world, sub, toPosePaths(space, paths), planned, plan);
  EXPECT_TRUE(shape.empty()) << shape;
  return validatePlan(world.map, planned, plan);
}

Outcome solveWith(Solver& solver, const World& world, const Subproblem& sub) {
  Outcome out;
  const auto t0 = std::chrono::steady_clock::now();
  out.result = solver.solve(sub);
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!out.result.success()) return out;
  out.shape_problem = toInstanceOrder(world, sub, out.result.paths, out.planned, out.plan);
  if (!out.shape_problem.empty()) return out;
  out.validation = validatePlan(world.map, out.planned, out.plan);
  if (out.validation.valid()) {
    std::vector<GridPose> targets;
    for (const Robot& r : out.planned.robots) targets.push_back(r.target);
    out.soc = planMetrics(out.plan, targets).soc;
  }
  return out;
}

Outcome solveWith(const std::string& name, const World& world, const Subproblem& sub) {
  const std::unique_ptr<Solver> solver = makeSolver(name);
  return solveWith(*solver, world, sub);
}

std::string describe(const Outcome& o) {
  std::ostringstream out;
  out << "status " << statusName(o.result.status) << ", reason '" << o.result.reason << "', "
      << o.result.paths.size() << " paths, " << o.wall_s << " s";
  if (!o.shape_problem.empty()) out << ", paths do not fit: " << o.shape_problem;
  if (o.result.success() && o.shape_problem.empty()) {
    out << ", "
        << (o.validation.valid() ? "valid plan, SOC " + std::to_string(o.soc)
                                 : "INVALID plan: " + o.validation.violation.message);
  }
  return out.str();
}

::testing::AssertionResult solvedValidly(const Outcome& o) {
  if (o.result.success() && o.shape_problem.empty() && o.validation.valid())
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << describe(o);
}

std::string staticFootprintClash(const World& world, const Subproblem& sub, const Outcome& o) {
  for (const StaticFootprint& s : sub.blocked) {
    const FootprintCells blocker(world.instance.robots.at(s.robot).footprint);
    for (std::size_t k = 0; k < o.plan.paths.size(); ++k) {
      const Robot& robot = o.planned.robots[k];
      const FootprintCells cells(robot.footprint);
      const Path& path = o.plan.paths[k];
      for (std::size_t t = 0; t < path.size(); ++t) {
        if (footprintsOverlap(cells, path[t], blocker, s.pose))
          return "robot '" + robot.id + "' at t=" + std::to_string(t) + " " + toString(path[t]) +
                 " overlaps the static footprint at " + toString(s.pose);
        if (t + 1 == path.size()) break;
        const auto action = actionBetween(path[t], path[t + 1], ActionModel{});
        if (action && sweepsOverlap(cells, path[t], *action, blocker, s.pose, Action::Wait))
          return "robot '" + robot.id + "' in step " + std::to_string(t) + " from " +
                 toString(path[t]) + " sweeps into the static footprint at " + toString(s.pose);
      }
    }
  }
  return "";
}

}  // namespace fleet_planner::test
