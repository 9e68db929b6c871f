#pragma once
/// Subcommands of fleet_planner_cli. Each add*Command registers its flags and a callback; a
/// callback that finds a problem sets the exit code (0 ok, 1 failed check, 2 bad input).
#include <CLI/CLI.hpp>

namespace fleet_planner::cli {

void addGenerateCommand(CLI::App& app);
void addCheckCommand(CLI::App& app);
void addGraphsCommand(CLI::App& app);
void addSolveCommand(CLI::App& app);
void addDecomposeCommand(CLI::App& app);
void addStressCommand(CLI::App& app);

void setExitCode(int code);
int exitCode();

}  // namespace fleet_planner::cli
