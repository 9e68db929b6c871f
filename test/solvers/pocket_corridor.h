#pragma once
/// A test world for the safe interval searches: a 1-wide corridor, 14 cells long, with one side
/// pocket below x = 6, and a runner that drives the whole corridor east (x = 0 to 13) on its
/// shortest path, already in a soft path table; a second robot, given, shares the corridor.
#include <utility>

#include "fleet_planner/solvers/search/soft_path_table.h"
#include "fleet_planner/solvers/search/space_time_astar.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {

struct PocketCorridor {
  explicit PocketCorridor(Robot other)
      : w(mapFromRows({"..............", "@@@@@@.@@@@@@@"}),
          {dot("runner", {0, 0, 0}, {13, 0, 0}), std::move(other)}),
        sub(allRobots(w)),
        space(sub),
        table(space) {
    const LowLevelResult r = spaceTimeAStar(space, 0, AgentConstraints{}, Deadline::in(5.0));
    if (r.outcome == LowLevelResult::Outcome::Found) {
      runner = r.path;
      table.insert(0, runner);
    }
  }

  World w;
  Subproblem sub;
  SearchSpace space;
  SoftPathTable table;
  StatePath runner;  ///< empty if the runner found no path (a broken test world)
};

}  // namespace fleet_planner::test
