#pragma once
/// Subcommands of fleet_planner_cli. Each add*Command registers its flags and a callback; a
/// callback that finds a problem sets the exit code (kExit* below).
#include <CLI/CLI.hpp>

namespace fleet_planner::cli {

void addGenerateCommand(CLI::App& app);
void addCheckCommand(CLI::App& app);
void addGraphsCommand(CLI::App& app);
void addSolveCommand(CLI::App& app);
void addDecomposeCommand(CLI::App& app);
void addStressCommand(CLI::App& app);

/// Exit statuses, also listed in --help.
constexpr int kExitFailedCheck = 1;    ///< invalid plan, unsolvable pre-check, illegal decomposition
constexpr int kExitBadInput = 2;       ///< a bad file, flag or robot (the message names it)
constexpr int kExitInternalError = 3;  ///< a plan that fails the validator, an unexpected exception
/// The --help footer that lists them.
constexpr const char* kExitStatusHelp =
    "Exit status: 0 done; 1 failed check (invalid plan, unsolvable pre-check, illegal decomposition); 2 bad "
    "input (the message names the file and line, the flag or the robot); 3 internal error (a plan that fails "
    "the validator: status INTERNAL_ERROR; an unexpected exception).";

void setExitCode(int code);
int exitCode();

}  // namespace fleet_planner::cli
