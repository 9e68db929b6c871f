#pragma once
/// The legality checker of a decomposition (paper: Preliminaries, "Decomposition of instance",
/// the simplified scenario), independent of the decomposition code: a decomposition is legal
/// when every robot of every subproblem has a path in its own state graph whose footprints and
/// swept cells avoid the target footprints of the robots of earlier subproblems and the start
/// footprints of the robots of later subproblems.
#include <string>
#include <vector>

#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/instance.h"

namespace fleet_planner {

struct LegalityReport {
  bool legal = true;
  int subproblem = -1;  ///< first failing subproblem (index in the given order)
  int robot = -1;       ///< first failing robot (instance index)
  std::string message;  ///< names the robot and the subproblem
};

/// Checks the ordered subproblems (robot lists; together they must hold every robot exactly
/// once, which is checked too).
LegalityReport checkLegality(const Instance& instance, const FleetGraphs& graphs,
                             const std::vector<std::vector<int>>& subproblems);

}  // namespace fleet_planner
