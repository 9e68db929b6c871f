#pragma once
// What the re-planning tests' hooks share: a request from the execution as a tracker sees it, the
// simulation's new plan from a re-plan's result, and the check that nobody else is released less
// far after it.
#include <memory>
#include <string>
#include <vector>

#include "execution_worlds.h"
#include "fleet_planner/execution/execution_simulation.h"
#include "fleet_planner/execution/execution_tracker.h"
#include "fleet_planner/execution/replanning.h"

namespace fleet_planner::test {

/// A test world ready to execute: its graphs, and its plan's cells and dependencies.
struct ExecutableWorld {
  explicit ExecutableWorld(const PlannedWorld& w)
      : graphs(graphsOf(w)), cells(w.instance, w.plan, w.model), deps(buildStepDependencies(cells)) {}
  FleetGraphs graphs;
  PlanCells cells;
  StepDependencies deps;
};

/// Runs `run(world, executable, seed)` for every test world and seeds 0 .. seeds - 1.
template <class Run>
void forEachWorldAndSeed(std::uint64_t seeds, Run run) {
  for (const PlannedWorld& w : testWorlds()) {
    const ExecutableWorld x(w);
    for (std::uint64_t seed = 0; seed < seeds; ++seed) run(w, x, seed);
  }
}

/// A request (nothing to plan yet) for `plan` of `instance` in `world`, at the progress and
/// releases `tracker` gives, with 5 s to plan.
inline ReplanRequest requestFrom(const PlannedWorld& world, const FleetGraphs& graphs, const Instance& instance,
                                 const Plan& plan, const ExecutionTracker& tracker, std::uint64_t seed) {
  ReplanRequest rq;
  rq.map = &world.map;
  rq.instance = &instance;
  rq.graphs = &graphs;
  rq.plan = &plan;
  for (int i = 0; i < tracker.robots(); ++i) {
    rq.progress.push_back(tracker.progress(i));
    rq.released.push_back(tracker.releasedUpTo(i));
  }
  rq.seed = seed;
  rq.deadline = Deadline::in(5.0);
  return rq;
}

/// The simulation's switch to a successful re-plan's result.
inline SimulatedReplan simulatedReplan(ReplanResult&& r, const ActionModel& model) {
  SimulatedReplan next;
  next.instance = std::make_shared<const Instance>(std::move(r.instance));
  next.plan = std::make_shared<const Plan>(std::move(r.plan));
  next.cells = std::make_shared<const PlanCells>(*next.instance, *next.plan, model);
  next.dependencies = std::move(r.dependencies);
  next.progress = std::move(r.progress);
  return next;
}

/// Every robot but `replanned`, resumed on the new plan, is released at least as far as before.
inline void checkReleasesKept(const ReplanRequest& rq, const ReplanResult& r, int replanned, const std::string& where,
                              std::vector<std::string>& failures) {
  const ExecutionTracker resumed(r.plan, r.dependencies, r.progress);
  for (int j = 0; j < resumed.robots(); ++j) {
    if (j != replanned && resumed.releasedUpTo(j) < rq.released[j])
      failures.push_back(where + "robot " + std::to_string(j) + " released less far");
  }
}

}  // namespace fleet_planner::test
