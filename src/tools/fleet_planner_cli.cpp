// fleet_planner_cli: generate instances, check plans, build state graphs, solve (see README).
#include <CLI/CLI.hpp>

#include <iostream>

#include "cli_commands.h"
#include "fleet_planner/runtime/errors.h"

int main(int argc, char** argv) {
  CLI::App app{"fleet_planner command-line tool: LA-MAPF instances, state graphs and plans"};
  app.require_subcommand(1);
  app.footer(fleet_planner::cli::kExitStatusHelp);
  fleet_planner::cli::addGenerateCommand(app);
  fleet_planner::cli::addCheckCommand(app);
  fleet_planner::cli::addGraphsCommand(app);
  fleet_planner::cli::addSolveCommand(app);
  fleet_planner::cli::addDecomposeCommand(app);
  fleet_planner::cli::addStressCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; a bad flag or value is bad input (CLI11's own codes vary).
    const int code = app.exit(e);
    return code == 0 ? 0 : fleet_planner::cli::kExitBadInput;
  } catch (const fleet_planner::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return fleet_planner::cli::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return fleet_planner::cli::kExitInternalError;
  }
  return fleet_planner::cli::exitCode();
}
