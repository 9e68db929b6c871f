// Exports the core's backends to pluginlib, so fleet_planner_node finds them by name the way it
// finds any other package's backend (the nav_core convention). See backends.xml.
#include <pluginlib/class_list_macros.hpp>

#include "fleet_planner/solvers/cbs/la_cbs.h"
#include "fleet_planner/solvers/lacam/la_lacam.h"
#include "fleet_planner/solvers/lns/la_lns.h"

PLUGINLIB_EXPORT_CLASS(fleet_planner::LaCbs, fleet_planner::Solver)
PLUGINLIB_EXPORT_CLASS(fleet_planner::LaLacam, fleet_planner::Solver)
PLUGINLIB_EXPORT_CLASS(fleet_planner::LaLns, fleet_planner::Solver)
