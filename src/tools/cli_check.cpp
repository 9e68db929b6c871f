// `check`: the independent validator on a plan file; `precheck`: the solvability pre-check.
#include "cli_common.h"
#include "fleet_planner/model/robot_cells.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/instance_check.h"
#include "fleet_planner/io/plan_io.h"
#include "fleet_planner/model/plan_validator.h"

namespace fleet_planner::cli {

namespace {

void addPrecheckCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("precheck", "solvability pre-check (exit 1 if a robot cannot be solved)");
  auto options = std::make_shared<ProblemOptions>();
  addProblemOptions(cmd, *options);
  cmd->callback([options] {
    const Problem p = loadProblem(*options);
    std::vector<Footprint> footprints;
    for (const auto& r : p.instance.robots) footprints.push_back(r.footprint);
    const FleetGraphs graphs(p.map, footprints);
    const SolvabilityReport report = checkSolvability(p.instance, graphs);
    nlohmann::json problems = nlohmann::json::array();
    for (const auto& pr : report.problems) problems.push_back(pr.reason);
    printJsonLine({{"agents", p.instance.robots.size()}, {"solvable", report.solvable()}, {"problems", problems}});
    if (!report.solvable()) setExitCode(1);
  });
}

// The longest move of the plan (cells between two consecutive poses of one heading).
int longestMove(const Plan& plan) {
  int longest = 0;
  for (const Path& path : plan.paths) {
    for (std::size_t t = 0; t + 1 < path.size(); ++t) {
      if (path[t].heading == path[t + 1].heading) longest = std::max(longest, moveLength(path[t], path[t + 1]));
    }
  }
  return longest;
}

}  // namespace

void addCheckCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("check", "validate a plan (exit 1 on the first violation)");
  auto options = std::make_shared<ProblemOptions>();
  auto plan_path = std::make_shared<std::string>();
  auto backward = std::make_shared<bool>(false);
  auto step = std::make_shared<int>(0);
  addProblemOptions(cmd, *options);
  cmd->add_option("--plan", *plan_path, "plan YAML file")->required();
  cmd->add_flag("--backward", *backward,
                "backward moves are legal (also when the plan file says backward_moves: true, as solve writes it)");
  cmd->add_option("--lattice-step", *step,
                  "longest legal move in cells (default 0: the plan's longest straight move, so that a plan "
                  "made on a lattice checks; each move's sweep is checked cell by cell either way)")
      ->check(CLI::NonNegativeNumber);
  cmd->callback([options, plan_path, backward, step] {
    const Problem p = loadProblem(*options);
    bool planned_backward = false;
    const Plan plan = loadPlan(*plan_path, p.instance, &planned_backward);
    ActionModel model;
    model.allow_backward = *backward || planned_backward;
    model.step = *step > 0 ? *step : std::max(1, longestMove(plan));
    const ValidationResult result = validatePlan(p.map, p.instance, plan, model);
    nlohmann::json j{{"valid", result.valid()}, {"agents", p.instance.robots.size()}};
    if (result.valid()) {
      const PlanMetrics m = planMetrics(plan, planTargets(p.instance, plan));
      j["soc"] = m.soc;
      j["makespan"] = m.makespan;
    } else {
      const Violation& v = result.violation;
      j["violation"] = violationName(v.kind);
      j["robot"] = v.robot >= 0 ? nlohmann::json(p.instance.robots[v.robot].id) : nlohmann::json();
      j["other"] = v.other >= 0 ? nlohmann::json(p.instance.robots[v.other].id) : nlohmann::json();
      j["time"] = v.time;
      j["message"] = v.message;
      setExitCode(1);
    }
    printJsonLine(j);
  });
  addPrecheckCommand(app);
}

}  // namespace fleet_planner::cli
