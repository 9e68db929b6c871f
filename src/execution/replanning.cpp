// Planning some robots of an executing plan again; see replanning.h.
#include "fleet_planner/execution/replanning.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <numeric>

#include "fleet_planner/execution/execution_tracker.h"
#include "fleet_planner/model/instance_check.h"
#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/model/robot_cells.h"
#include "fleet_planner/planning/lattice.h"
#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/solvers/registry.h"

namespace fleet_planner {

namespace {

/// Why the request cannot be taken ("" if it can).
std::string requestProblem(const ReplanRequest& rq) {
  if (!rq.map || !rq.instance || !rq.graphs || !rq.plan) return "re-plan without a map, robots, graphs or plan";
  const std::size_t n = rq.instance->robots.size();
  if (rq.plan->paths.size() != n || rq.progress.size() != n || rq.released.size() != n ||
      static_cast<std::size_t>(rq.graphs->numRobots()) != n) {
    return "re-plan: the plan, the progress, the releases and the graphs must have one entry per robot (" +
           std::to_string(n) + ")";
  }
  for (std::size_t i = 0; i < n; ++i) {
    const int last = static_cast<int>(rq.plan->paths[i].size()) - 1;
    if (rq.progress[i] < 0 || rq.progress[i] > last || rq.released[i] < rq.progress[i] || rq.released[i] > last) {
      return robotLabel(rq.instance->robots[i]) + ": progress " + std::to_string(rq.progress[i]) + " and release " +
             std::to_string(rq.released[i]) + " are not states 0.." + std::to_string(last) + " in that order";
    }
  }
  std::vector<int> seen;
  for (int r : rq.robots) {
    if (r < 0 || r >= static_cast<int>(n)) return "re-plan: no robot " + std::to_string(r);
    if (std::count(rq.robots.begin(), rq.robots.end(), r) > 1) return "re-plan: robot " + std::to_string(r) + " twice";
  }
  for (const NewTarget& t : rq.targets) {
    if (t.robot < 0 || t.robot >= static_cast<int>(n)) return "re-plan: no robot " + std::to_string(t.robot) + " for a new target";
  }
  for (const MovedRobot& m : rq.moved) {
    if (m.robot < 0 || m.robot >= static_cast<int>(n)) return "re-plan: no robot " + std::to_string(m.robot) + " moved";
    if (m.yaw) continue;  // its body at a yaw off the grid, and its turn, are connectToLattice's to check
    if (std::string why = poseProblem(*rq.map, rq.graphs->cells(m.robot), m.pose); !why.empty())
      return robotLabel(rq.instance->robots[m.robot]) + " stands off its path at " + toString(m.pose) + ": " + why;
  }
  for (const AvoidedSteps& a : rq.avoid) {
    if (a.robot < 0 || a.robot >= static_cast<int>(n)) return "re-plan: no robot " + std::to_string(a.robot) + " to avoid";
  }
  return "";
}

ReplanResult failure(SolveStatus status, std::string reason) {
  ReplanResult r;
  r.status = status;
  r.reason = std::move(reason);
  return r;
}

/// Everything one call needs, and its steps in order.
class Replanner {
 public:
  Replanner(const ReplanRequest& rq, std::vector<int> robots)
      : rq_(rq), robots_(std::move(robots)), model_(rq.graphs->graph(0).actionModel()), plan_(*rq.plan),
        instance_(*rq.instance) {
    for (const NewTarget& t : rq.targets) {
      instance_.robots[t.robot].target = t.target;
      instance_.robots[t.robot].target_yaw = t.target_yaw;
    }
    for (const MovedRobot& m : rq.moved) moved_[m.robot] = &m;
    bool all_arrived = true;
    for (int a : robots_) {
      if (moved_.count(a)) continue;
      start_time_ = std::max(start_time_, rq.released[a]);
      all_arrived = all_arrived && rq.released[a] == lastState(a);
    }
    // Robots that have arrived, and robots moved off their paths, start their new ways no
    // earlier than the slowest other robot's progress: before it, the others' paths are what
    // they have already driven.
    slowest_ = -1;
    for (int j = 0; j < static_cast<int>(plan_.paths.size()); ++j) {
      if (!std::count(robots_.begin(), robots_.end(), j)) slowest_ = slowest_ < 0 ? rq.progress[j] : std::min(slowest_, rq.progress[j]);
    }
    if (all_arrived || !moved_.empty()) start_time_ = std::max(start_time_, slowest_);
    if (slowest_ < 0) slowest_ = start_time_;  // nobody else: no history to check
    progress_ = rq.progress;
    for (const auto& [a, m] : moved_) progress_[a] = std::min(progress_[a], start_time_);
  }

  /// The robot stands off its plan (ReplanRequest::moved).
  bool moved(int robot) const { return moved_.count(robot) > 0; }

  /// The robots' connections from their released states to their targets. A robot that rests at
  /// a yaw off the grid (its start yaw, not yet turned from, or its previous target's) turns from
  /// it first.
  std::string connect() {
    Instance sub;
    for (int a : robots_) {
      const Robot& old = rq_.instance->robots[a];
      Robot r = instance_.robots[a];
      const int k = rq_.released[a];
      r.start = rq_.plan->paths[a][k];
      r.start_turn = 0;
      if (const auto m = moved_.find(a); m != moved_.end()) {
        r.start = m->second->pose;
        r.start_yaw = m->second->yaw;
        r.conflicts_from = slowest_;  // its history becomes a rest where it stands (see replanning.h)
      } else if (k == lastState(a) && old.target_yaw) {
        r.start_yaw = old.target_yaw;
        r.conflicts_from = k;  // its history becomes a rest there: it only meets steps done before it arrived
      } else if (!old.start_yaw || k > old.start_turn) {
        r.start_yaw.reset();  // it has turned from its start yaw already
      }
      sub.robots.push_back(r);
    }
    sub_graphs_ = std::make_unique<FleetGraphs>(*rq_.graphs, robots_);
    lattice_ = connectToLattice(*rq_.map, sub, *sub_graphs_, model_.step);
    bad_pose_ = !lattice_.problems.empty();
    if (lattice_.problem.empty()) {
      for (std::size_t i = 0; i < robots_.size(); ++i) {
        Robot& r = instance_.robots[robots_[i]];
        if (moved(robots_[i])) {
          r.start = sub.robots[i].start;
          r.start_yaw.reset();
          r.start_turn = 0;
          r.conflicts_from = sub.robots[i].conflicts_from;
        }
        if (!sub.robots[i].start_yaw) continue;
        r.start = lattice_.connections[i].prefix.front();
        r.start_yaw = sub.robots[i].start_yaw;
        r.start_turn = start_time_;
        r.conflicts_from = std::max(r.conflicts_from, sub.robots[i].conflicts_from);
      }
    }
    return lattice_.problem;
  }

  /// The problem is a start or target no lattice can connect (connectToLattice's problems).
  bool badPose() const { return bad_pose_; }

  int lastState(int robot) const { return static_cast<int>(rq_.plan->paths[robot].size()) - 1; }

  /// The robots' lattice paths around everybody else, from the time their connections end.
  SolveResult solveLattice() {
    std::size_t prefix = 1;
    for (const auto& c : lattice_.connections) prefix = std::max(prefix, c.prefix.size());
    lattice_time_ = start_time_ + static_cast<int>(prefix) - 1;
    lattice_instance_ = *rq_.instance;
    for (std::size_t i = 0; i < robots_.size(); ++i) lattice_instance_.robots[robots_[i]] = lattice_.instance.robots[i];
    Subproblem sp;
    sp.instance = &lattice_instance_;
    sp.graphs = rq_.graphs;
    sp.robots = robots_;
    sp.deadline = rq_.deadline;
    sp.seed = rq_.seed;
    for (int j = 0; j < static_cast<int>(plan_.paths.size()); ++j) {
      if (std::count(robots_.begin(), robots_.end(), j)) continue;
      const Path& p = rq_.plan->paths[j];
      const int from = std::min(lattice_time_, static_cast<int>(p.size()) - 1);
      sp.moving.push_back(cutPath(j, from, static_cast<int>(p.size()) - 1));
      sp.moving.back().held_through = rq_.released[j] - lattice_time_;
    }
    // Avoided steps: their bodies as static obstacles (the search's distances see them too) and
    // their sweeps held for good (the turns' corners).
    for (const AvoidedSteps& a : rq_.avoid) {
      if (std::count(robots_.begin(), robots_.end(), a.robot)) continue;
      const Path& p = rq_.plan->paths[a.robot];
      const int from = rq_.progress[a.robot];
      const int through = std::max(from, std::min(a.through, static_cast<int>(p.size()) - 1));
      for (int k = from; k <= through; ++k) {
        if (k == from || p[k] != p[k - 1]) sp.blocked.push_back({a.robot, p[k]});
      }
      MovingObstacle held = cutPath(a.robot, from, through);
      held.held_through = static_cast<int>(held.path.size()) - 1;
      held.held_for_good = true;
      sp.moving.push_back(std::move(held));
    }
    std::unique_ptr<Solver> solver = makeSolver(rq_.backend);
    if (!solver->avoidsMovingObstacles()) {
      SolveResult wrong;
      wrong.status = SolveStatus::InvalidInput;
      wrong.reason = "re-plan: backend '" + rq_.backend + "' does not avoid moving obstacles";
      return wrong;
    }
    return solver->solve(sp);
  }

  /// Robot j's states from..to as a moving obstacle from step 0, with the turns from its start
  /// yaw and to its target yaw where they are part of it (a path of two poses then at least).
  MovingObstacle cutPath(int j, int from, int to) const {
    const Robot& r = rq_.instance->robots[j];
    const Path& p = rq_.plan->paths[j];
    const int last = static_cast<int>(p.size()) - 1;
    MovingObstacle m{j, Path(p.begin() + from, p.begin() + to + 1)};
    if (from <= r.start_turn && r.start_yaw) {
      m.start_yaw = r.start_yaw;
      m.start_turn = r.start_turn - from;
    }
    if (to == last && r.target_yaw) m.target_yaw = r.target_yaw;
    const std::size_t turns = (m.start_yaw ? m.start_turn + 1 : 0) + (m.target_yaw ? 1 : 0);
    if (m.path.size() < turns + 1) m.path.resize(turns + 1, m.path.back());
    return m;
  }

  /// Each robot's new path: its path up to its release, a wait until the common start, its
  /// start's connection, its lattice path and its target's connection at the earliest step at
  /// which it meets nobody. False with `problem` if some target's connection never does.
  bool assemble(const std::vector<Path>& lattice_paths, std::string& problem) {
    const int lattice_start = lattice_time_;
    std::vector<int> arrival(robots_.size());
    for (std::size_t i = 0; i < robots_.size(); ++i) {
      const int a = robots_[i];
      const Path& old = rq_.plan->paths[a];
      const Path& prefix = lattice_.connections[i].prefix;
      // A robot resting at a yaw rests there from the start on (the same place, so its history
      // keeps its cells), and turns when its new way begins.
      Path p = moved(a) || (instance_.robots[a].start_yaw && instance_.robots[a].start_turn == start_time_)
                   ? Path(1, prefix.front())
                   : Path(old.begin(), old.begin() + rq_.released[a] + 1);
      p.resize(static_cast<std::size_t>(start_time_) + 1, p.back());
      p.insert(p.end(), prefix.begin() + 1, prefix.end());
      p.resize(static_cast<std::size_t>(lattice_start) + 1, p.back());
      p.insert(p.end(), lattice_paths[i].begin() + 1, lattice_paths[i].end());
      arrival[i] = static_cast<int>(p.size()) - 1;
      plan_.paths[a] = std::move(p);
    }
    const int n = static_cast<int>(plan_.paths.size());
    std::vector<Robot> seen = instance_.robots;  // re-planned robots end on their lattice targets until placed
    for (int a : robots_) seen[a].target_yaw.reset();
    std::vector<std::unique_ptr<RobotCells>> cells(n);
    for (int j = 0; j < n; ++j) cells[j] = std::make_unique<RobotCells>(seen[j], rq_.graphs->cells(j), plan_.paths[j]);
    std::vector<std::size_t> order(robots_.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return arrival[x] < arrival[y]; });
    int horizon = 0;
    for (const Path& p : plan_.paths) horizon = std::max(horizon, static_cast<int>(p.size()));
    for (std::size_t i : order) {
      const int a = robots_[i];
      const Path& suffix = lattice_.connections[i].suffix;
      const Robot& robot = instance_.robots[a];
      bool placed = suffix.size() == 1;
      for (int t = arrival[i]; !placed && t <= horizon + static_cast<int>(suffix.size()); ++t) {
        Path candidate(plan_.paths[a].begin(), plan_.paths[a].begin() + arrival[i] + 1);
        candidate.resize(static_cast<std::size_t>(t) + 1, candidate.back());
        candidate.insert(candidate.end(), suffix.begin() + 1, suffix.end());
        const RobotCells mine(robot, rq_.graphs->cells(a), candidate);
        bool clash = false;
        for (int j = 0; j < n && !clash; ++j) {
          if (j != a) clash = pathsMeet(mine, candidate, *cells[j], plan_.paths[j], t, model_);
        }
        if (clash) continue;
        plan_.paths[a] = std::move(candidate);
        cells[a] = std::make_unique<RobotCells>(robot, rq_.graphs->cells(a), plan_.paths[a]);
        horizon = std::max(horizon, static_cast<int>(plan_.paths[a].size()));
        placed = true;
      }
      if (!placed) {
        problem = robotLabel(robot) + ": the connection from its lattice target to its target is never clear of the other robots";
        return false;
      }
    }
    return true;
  }

  /// "" when no other robot is released less far under `dependencies` than it already is.
  std::string releasesKept(const StepDependencies& dependencies) const {
    const ExecutionTracker tracker(plan_, dependencies, progress_);
    for (int j = 0; j < tracker.robots(); ++j) {
      if (std::count(robots_.begin(), robots_.end(), j)) continue;
      if (tracker.releasedUpTo(j) < rq_.released[j]) {
        const auto holder = tracker.blockedBy(j);
        return robotLabel(rq_.instance->robots[j]) + " is released to state " + std::to_string(rq_.released[j]) +
               " but would have to wait at state " + std::to_string(tracker.releasedUpTo(j)) +
               (holder ? " for " + robotLabel(rq_.instance->robots[holder->robot]) : std::string()) +
               "'s new path";
      }
    }
    return "";
  }

  const Plan& plan() const { return plan_; }
  const Instance& instance() const { return instance_; }
  const std::vector<int>& progress() const { return progress_; }
  /// The states every robot has reached: what comes before is the past, not checked again.
  int done() const { return *std::min_element(progress_.begin(), progress_.end()); }
  bool anyMoved() const { return !moved_.empty(); }
  int startTime() const { return start_time_; }
  const ActionModel& model() const { return model_; }

 private:
  const ReplanRequest& rq_;
  const std::vector<int> robots_;
  const ActionModel model_;
  Plan plan_;
  Instance instance_;                ///< with the new targets and the rests at yaws
  int start_time_ = 0;
  int slowest_ = 0;  ///< the slowest other robot's progress
  std::map<int, const MovedRobot*> moved_;
  std::vector<int> progress_;  ///< what each robot resumes from
  int lattice_time_ = 0;
  bool bad_pose_ = false;
  std::unique_ptr<FleetGraphs> sub_graphs_;
  LatticeInstance lattice_;
  Instance lattice_instance_;
};

}  // namespace

ReplanResult replanRobots(const ReplanRequest& request) {
  const auto started = std::chrono::steady_clock::now();
  std::string stages;  // "connect 0.01 s, search 0.20 s, ...": where the time went
  auto lap = [&, last = started](const char* stage) mutable {
    const auto now = std::chrono::steady_clock::now();
    char text[64];
    std::snprintf(text, sizeof(text), "%s%s %.3f s", stages.empty() ? "" : ", ", stage,
                  std::chrono::duration<double>(now - last).count());
    stages += text;
    last = now;
  };
  auto finish = [&](ReplanResult r) {
    r.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    r.stages = stages;
    return r;
  };
  if (std::string why = requestProblem(request); !why.empty()) return finish(failure(SolveStatus::InvalidInput, why));
  std::vector<int> robots;
  for (int a : request.robots) {
    if (request.released[a] < static_cast<int>(request.plan->paths[a].size()) - 1) robots.push_back(a);
  }
  for (const NewTarget& t : request.targets) robots.push_back(t.robot);
  for (const MovedRobot& m : request.moved) robots.push_back(m.robot);
  std::sort(robots.begin(), robots.end());
  robots.erase(std::unique(robots.begin(), robots.end()), robots.end());
  if (robots.empty()) {
    ReplanResult same;
    same.status = SolveStatus::Success;
    same.plan = *request.plan;
    same.instance = *request.instance;
    same.dependencies = buildStepDependencies(*request.instance, same.plan, request.graphs->graph(0).actionModel(),
                                              *std::min_element(request.progress.begin(), request.progress.end()));
    same.progress = request.progress;
    return finish(std::move(same));
  }
  try {
    Replanner replanner(request, robots);
    const std::string connect_problem = replanner.connect();
    lap("connect");
    if (const std::string& why = connect_problem; !why.empty()) {
      return finish(failure(replanner.badPose() ? SolveStatus::InvalidInput : SolveStatus::Infeasible, why));
    }
    SolveResult solved = replanner.solveLattice();
    lap("search");
    if (!solved.success()) return finish(failure(solved.status, solved.reason));
    std::string problem;
    const bool assembled = replanner.assemble(solved.paths, problem);
    lap("assemble");
    if (!assembled) return finish(failure(SolveStatus::Infeasible, problem));
    const ValidationResult check =
        validatePlanChanges(*request.map, replanner.instance(), replanner.plan(), replanner.model(), robots, replanner.done());
    lap("validate");
    if (!check.valid() && replanner.anyMoved()) {
      // A moved robot's rest where it stands is no searched step: some robot must pass there first.
      return finish(failure(SolveStatus::Infeasible, "a robot stands where another has still to pass: " + check.violation.message));
    }
    if (!check.valid()) {
      return finish(failure(SolveStatus::InternalError,
                            "internal error: the re-planned plan fails validation: " + check.violation.message + " (new paths from step " + std::to_string(replanner.startTime()) + ")"));
    }
    ReplanResult out;
    out.dependencies = buildStepDependencies(replanner.instance(), replanner.plan(), replanner.model(), replanner.done());
    lap("dependencies");
    const std::string kept = replanner.releasesKept(out.dependencies);
    lap("releases");
    if (const std::string& why = kept; !why.empty()) {
      return finish(failure(SolveStatus::Infeasible, why));
    }
    out.status = SolveStatus::Success;
    out.plan = replanner.plan();
    out.instance = replanner.instance();
    out.progress = replanner.progress();
    return finish(std::move(out));
  } catch (const InvalidInput& e) {
    return finish(failure(SolveStatus::InvalidInput, e.what()));
  } catch (const DeadlineExpired& e) {
    return finish(failure(SolveStatus::Timeout, e.what()));
  }
}

}  // namespace fleet_planner
