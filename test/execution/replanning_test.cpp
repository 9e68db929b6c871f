// Re-planning robots of an executing plan (replanning.h): a robot stopped for good holds those
// waiting for it; each of them, once it waits, is planned again around it while the others keep
// driving. Every new plan passes the validator, keeps the other robots' paths and what they were
// released to, and the execution, with random delays, ends with no collision and nobody stuck.
#include "fleet_planner/execution/replanning.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <iostream>
#include <memory>

#include "execution_worlds.h"
#include "replan_hooks.h"
#include "fleet_planner/execution/execution_simulation.h"
#include "fleet_planner/solvers/search/reservation_table.h"

namespace fleet_planner::test {
namespace {

constexpr double kForever = 1e6;  // the stopped robot's hold ends long after everybody else's plan

/// The map cells of a placed set.
std::set<std::pair<int, int>> mapCells(const PlacedCells& p) {
  std::set<std::pair<int, int>> out;
  for (const Cell& c : p.cells->cells()) out.insert({p.at.x + c.x, p.at.y + c.y});
  return out;
}

/// Every robot stands where it stood: its cells at its progress are the same in both plans.
void checkStandsStill(const ReplanRequest& rq, const ReplanResult& r, const ActionModel& model,
                      const std::string& where, std::vector<std::string>& failures) {
  const PlanCells before(*rq.instance, *rq.plan, model), after(r.instance, r.plan, model);
  for (int j = 0; j < before.robots(); ++j) {
    if (mapCells(before.atRest(j, rq.progress[j])) != mapCells(after.atRest(j, rq.progress[j])))
      failures.push_back(where + "robot " + std::to_string(j) + " covers other cells at its progress");
  }
}

/// Plans, as a node would, every robot that waits for the stopped one `stopped`.
struct BlockedReplanner {
  const PlannedWorld* world = nullptr;
  const FleetGraphs* graphs = nullptr;
  int stopped = -1;
  std::uint64_t seed = 0;
  int attempts = 0, successes = 0;
  std::map<std::string, int> refused;  ///< by status
  std::vector<std::string> failures;  ///< what the checks below found wrong

  std::optional<SimulatedReplan> operator()(const ExecutionSnapshot& s) {
    const ExecutionTracker& tracker = *s.tracker;
    const int n = tracker.robots();
    if (attempts >= 4) return std::nullopt;
    for (int a = 0; a < n; ++a) {
      const auto holder = tracker.blockedBy(a);
      if (a == stopped || s.moving[a] || tracker.done(a) || !holder || holder->robot != stopped ||
          tracker.releasedUpTo(a) != tracker.progress(a))
        continue;
      ReplanRequest rq = requestFrom(*world, *graphs, world->instance, plan(s), tracker, seed);
      rq.robots = {a};
      rq.avoid = {{stopped, holder->state}};
      ++attempts;
      ReplanResult r = replanRobots(rq);
      if (!r.success()) {
        ++refused[statusName(r.status)];
        continue;
      }
      check(rq, r, a);
      ++successes;
      SimulatedReplan next = simulatedReplan(std::move(r), world->model);
      current_ = next.plan;
      return next;
    }
    return std::nullopt;
  }

  const Plan& plan(const ExecutionSnapshot&) { return current_ ? *current_ : world->plan; }

  void check(const ReplanRequest& rq, const ReplanResult& r, int a) {
    const std::string where = world->name + " seed " + std::to_string(seed) + " robot " + std::to_string(a) + ": ";
    const ValidationResult v = validatePlan(world->map, world->instance, r.plan, world->model);
    if (!v.valid()) failures.push_back(where + "invalid plan: " + v.violation.message);
    for (int j = 0; j < static_cast<int>(r.plan.paths.size()); ++j) {
      const Path& before = rq.plan->paths[j];
      const Path& after = r.plan.paths[j];
      if (j != a && after != before) failures.push_back(where + "robot " + std::to_string(j) + "'s path changed");
      if (j == a && !std::equal(before.begin(), before.begin() + rq.progress[a] + 1, after.begin()))
        failures.push_back(where + "its path up to its progress changed");
      if (j == a && (after.back() != before.back())) failures.push_back(where + "its new path ends elsewhere");
    }
    checkStandsStill(rq, r, world->model, where, failures);
    checkReleasesKept(rq, r, a, where, failures);
  }

  std::shared_ptr<const Plan> current_;
};

TEST(Replanning, RobotsWaitingForAStoppedOneArePlannedAroundItAndEverybodyArrivesSafely) {
  int runs = 0, replans = 0, attempts = 0, bypassed = 0;
  std::map<std::string, int> refused;
  forEachWorldAndSeed(6, [&](const PlannedWorld& w, const ExecutableWorld& x, std::uint64_t seed) {
    const int n = x.cells.robots();
    const int stopped = static_cast<int>(seed % n);
    BlockedReplanner replanner;
    replanner.world = &w;
    replanner.graphs = &x.graphs;
    replanner.stopped = stopped;
    replanner.seed = seed;
    DelayModel delays;
    delays.slowdown = 1.0;
    delays.stop_probability = 0.05;
    const std::vector<Hold> holds = {{stopped, 1.5, kForever}};
    const SimulationResult r = simulateExecution(x.cells, &x.deps, delays, seed, holds, std::ref(replanner));
    ASSERT_EQ(r.outcome, SimulationResult::Outcome::Completed) << w.name << " seed " << seed << ": " << r.message;
    for (const std::string& f : replanner.failures) ADD_FAILURE() << f;
    replans += replanner.successes;
    for (const auto& [status, count] : replanner.refused) refused[status] += count;
    // Robots that arrived while the stopped one still stood: none of them waited for it.
    for (int i = 0; i < n; ++i) bypassed += i != stopped && replanner.successes > 0 && r.arrivals[i] < kForever;
    attempts += replanner.attempts;
    ++runs;
  });
  std::cout << runs << " runs, " << attempts << " re-plans asked, " << replans << " made; refused:";
  for (const auto& [status, count] : refused) std::cout << " " << status << " " << count;
  std::cout << "\n";
  EXPECT_EQ(refused.count("INTERNAL_ERROR"), 0u);
  // How many find a way varies with the machine's load (7-17 of about 330 seen): LA-LNS's joint
  // repair gets a share of the time left. The stopped robot usually stands on the way or the goal.
  EXPECT_GE(replans, 5);
  EXPECT_GE(bypassed, replans);
  EXPECT_GE(attempts, replans);
}

// An open hall: 'b' drives down the middle behind 'a', which turns off to the side but stops for
// good at its start. Without a re-plan 'b' waits until 'a' comes back; re-planned around it, 'b'
// arrives long before.
TEST(Replanning, AFollowerPassesARobotThatStoppedForGood) {
  std::vector<std::string> rows(9, std::string(24, '.'));
  PlannedWorld w;
  w.map = mapFromRows(rows);
  w.instance.robots.push_back(makeRobot("a", Footprint::circle(0.9), {9, 4, 0}, {12, 7, 1}));
  w.instance.robots.push_back(makeRobot("b", Footprint::circle(0.9), {2, 4, 0}, {20, 4, 0}));
  PlanningOptions o = executionPlanning(1, 1);
  o.time_limit = 5.0;
  const PlanningResult planned = planFleet(w.map, w.instance, o);
  ASSERT_TRUE(planned.success()) << planned.reason;
  w.plan = planned.plan;
  w.name = "corridor";
  const FleetGraphs graphs = graphsOf(w);
  const PlanCells cells(w.instance, w.plan, w.model);
  const StepDependencies deps = buildStepDependencies(cells);
  const std::vector<Hold> holds = {{0, 0.0, kForever}};
  const SimulationResult waited = simulateExecution(cells, &deps, DelayModel{}, 3, holds);
  ASSERT_EQ(waited.outcome, SimulationResult::Outcome::Completed) << waited.message;
  EXPECT_GT(waited.arrivals[1], kForever);
  BlockedReplanner replanner;
  replanner.world = &w;
  replanner.graphs = &graphs;
  replanner.stopped = 0;
  const SimulationResult passed = simulateExecution(cells, &deps, DelayModel{}, 3, holds, std::ref(replanner));
  ASSERT_EQ(passed.outcome, SimulationResult::Outcome::Completed) << passed.message;
  for (const std::string& f : replanner.failures) ADD_FAILURE() << f;
  EXPECT_EQ(replanner.successes, 1);
  EXPECT_LT(passed.arrivals[1], 100.0);
}

/// Gives each robot that has arrived, while others still drive, a new target: back to its start
/// (at its start yaw), once.
struct GoalGiver {
  const PlannedWorld* world = nullptr;
  const FleetGraphs* graphs = nullptr;
  std::uint64_t seed = 0;
  std::shared_ptr<const Instance> instance;
  std::shared_ptr<const Plan> plan;
  std::vector<bool> given;
  int asked = 0, made = 0;
  std::vector<std::string> failures;

  std::optional<SimulatedReplan> operator()(const ExecutionSnapshot& s) {
    const ExecutionTracker& tracker = *s.tracker;
    const int n = tracker.robots();
    if (given.empty()) given.assign(n, false);
    if (tracker.done()) return std::nullopt;
    for (int a = 0; a < n; ++a) {
      if (given[a] || !tracker.done(a)) continue;
      given[a] = true;
      const Instance& now = instance ? *instance : world->instance;
      ReplanRequest rq = requestFrom(*world, *graphs, now, plan ? *plan : world->plan, tracker, seed);
      const Robot& original = world->instance.robots[a];
      rq.targets = {{a, original.start, original.start_yaw}};
      ++asked;
      ReplanResult r = replanRobots(rq);
      if (r.status == SolveStatus::InternalError) failures.push_back(world->name + ": " + r.reason);
      if (!r.success()) continue;
      ++made;
      check(rq, r, a);
      SimulatedReplan next = simulatedReplan(std::move(r), world->model);
      instance = next.instance;
      plan = next.plan;
      return next;
    }
    return std::nullopt;
  }

  void check(const ReplanRequest& rq, const ReplanResult& r, int a) {
    const std::string where = world->name + " seed " + std::to_string(seed) + " robot " + std::to_string(a) + ": ";
    const Robot& robot = r.instance.robots[a];
    if (robot.target.x != world->instance.robots[a].start.x || robot.target.y != world->instance.robots[a].start.y)
      failures.push_back(where + "its target is not its new one");
    // Its history is a rest at its previous target from the time it arrived there: conflicts are
    // checked from then on, and earlier new goals' histories likewise.
    for (std::size_t j = 0; j < r.instance.robots.size(); ++j) {
      const int expected = static_cast<int>(j) == a && rq.instance->robots[a].target_yaw
                               ? rq.progress[a]
                               : rq.instance->robots[j].conflicts_from;
      if (r.instance.robots[j].conflicts_from != expected)
        failures.push_back(where + "robot " + std::to_string(j) + " is checked from step " +
                           std::to_string(r.instance.robots[j].conflicts_from));
    }
    const ValidationResult v = validatePlan(world->map, r.instance, r.plan, world->model);
    if (!v.valid()) failures.push_back(where + "invalid plan: " + v.violation.message);
    checkStandsStill(rq, r, world->model, where, failures);
    for (std::size_t j = 0; j < r.plan.paths.size(); ++j) {
      if (static_cast<int>(j) != a && r.plan.paths[j] != rq.plan->paths[j])
        failures.push_back(where + "robot " + std::to_string(j) + "'s path changed");
    }
  }
};

TEST(Replanning, RobotsThatArriveGetNewGoalsWhileTheOthersDrive) {
  int runs = 0, asked = 0, made = 0;
  forEachWorldAndSeed(4, [&](const PlannedWorld& w, const ExecutableWorld& x, std::uint64_t seed) {
    GoalGiver giver;
    giver.world = &w;
    giver.graphs = &x.graphs;
    giver.seed = seed;
    const SimulationResult r = simulateExecution(x.cells, &x.deps, DelayModel{}, seed, {}, std::ref(giver));
    ASSERT_EQ(r.outcome, SimulationResult::Outcome::Completed) << w.name << " seed " << seed << ": " << r.message;
    for (const std::string& f : giver.failures) ADD_FAILURE() << f;
    asked += giver.asked;
    made += giver.made;
    ++runs;
  });
  std::cout << runs << " runs, " << asked << " new goals asked, " << made << " planned\n";
  EXPECT_GE(made, asked / 3);
}

TEST(Replanning, SameRequestSamePlan) {
  const PlannedWorld& w = testWorlds().back();
  const FleetGraphs graphs = graphsOf(w);
  ReplanRequest rq;
  rq.map = &w.map;
  rq.instance = &w.instance;
  rq.graphs = &graphs;
  rq.plan = &w.plan;
  const int n = static_cast<int>(w.plan.paths.size());
  rq.progress.assign(n, 0);
  rq.released.assign(n, 0);
  rq.robots = {0, n - 1};
  const ReplanResult a = replanRobots(rq), b = replanRobots(rq);
  ASSERT_TRUE(a.success()) << a.reason;
  EXPECT_EQ(a.plan.paths, b.plan.paths);
  EXPECT_TRUE(validatePlan(w.map, w.instance, a.plan, w.model).valid());
}

TEST(Replanning, BadRequestsAreAnsweredWithAReason) {
  const PlannedWorld& w = testWorlds().front();
  const FleetGraphs graphs = graphsOf(w);
  ReplanRequest rq;
  rq.map = &w.map;
  rq.instance = &w.instance;
  rq.graphs = &graphs;
  rq.plan = &w.plan;
  const int n = static_cast<int>(w.plan.paths.size());
  rq.progress.assign(n, 0);
  rq.released.assign(n, 0);
  rq.robots = {n};
  ReplanResult r = replanRobots(rq);
  EXPECT_EQ(r.status, SolveStatus::InvalidInput);
  EXPECT_NE(r.reason.find("no robot"), std::string::npos) << r.reason;
  rq.robots = {0};
  rq.progress[0] = static_cast<int>(w.plan.paths[0].size());
  r = replanRobots(rq);
  EXPECT_EQ(r.status, SolveStatus::InvalidInput);
  EXPECT_NE(r.reason.find(w.instance.robots[0].id), std::string::npos) << r.reason;
}

TEST(Replanning, ReleasedStepsOfAMovingObstacleAreTakenFromTheStart) {
  const GridMap map = freeMap(20, 5);
  Instance instance;
  instance.robots.push_back(makeRobot("m", Footprint::circle(0.4), {2, 2, 0}, {8, 2, 0}));
  const FleetGraphs graphs(map, {instance.robots[0].footprint});
  MovingObstacle m{0, {{2, 2, 0}, {3, 2, 0}, {4, 2, 0}, {5, 2, 0}, {6, 2, 0}}};
  const ReservationTable plain(20, 5, {m}, graphs, ActionModel{});
  EXPECT_FALSE(plain.taken(5, 2, 0));  // reached at step 3
  m.held_through = 3;
  const ReservationTable held(20, 5, {m}, graphs, ActionModel{});
  EXPECT_TRUE(held.taken(5, 2, 0));
  EXPECT_TRUE(held.taken(3, 2, 1));
  EXPECT_FALSE(held.taken(2, 2, 10));  // left at its plan's time
  m.held_for_good = true;
  const ReservationTable good(20, 5, {m}, graphs, ActionModel{});
  EXPECT_TRUE(good.taken(2, 2, 10));
}

}  // namespace
}  // namespace fleet_planner::test
