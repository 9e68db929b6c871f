// A plan executed by robots that are late at random; see execution_simulation.h.
#include "fleet_planner/execution/execution_simulation.h"

#include <optional>
#include <vector>

#include "fleet_planner/execution/execution_tracker.h"
#include "fleet_planner/runtime/random.h"

namespace fleet_planner {

namespace {

class Simulation {
 public:
  Simulation(const PlanCells& cells, const StepDependencies* deps, const DelayModel& delays, std::uint64_t seed,
             const std::vector<Hold>& holds, const ReplanHook& replan)
      : cells_(&cells), delays_(delays), rng_(seed), progress_(cells.robots(), 0), moving_(cells.robots(), false),
        end_(cells.robots(), 0.0), holds_(holds), replan_(replan) {
    result_.arrivals.assign(cells.robots(), -1.0);
    for (int i = 0; i < cells.robots(); ++i) {
      if (cells.lastState(i) == 0) result_.arrivals[i] = 0.0;
    }
    if (deps != nullptr) {
      plan_.paths.reserve(cells.robots());
      for (int i = 0; i < cells.robots(); ++i) plan_.paths.push_back(cells.path(i));
      tracker_.emplace(plan_, *deps);
    }
  }

  SimulationResult run() {
    for (int i = 0; i < cells_->robots(); ++i) {
      if (collides(i)) return result_;
    }
    if (!startReady() || !maybeReplan()) return result_;
    for (;;) {
      int next = -1;
      for (int i = 0; i < cells_->robots(); ++i) {
        if (moving_[i] && (next < 0 || end_[i] < end_[next])) next = i;
      }
      // A robot held now wakes at the end of its hold: an event too.
      double wake = -1.0;
      for (const Hold& h : holds_) {
        if (h.until > now_ && h.from <= now_ && progress_[h.robot] < cells_->lastState(h.robot) &&
            (wake < 0 || h.until < wake))
          wake = h.until;
      }
      if (next < 0 && wake < 0) break;
      if (wake >= 0 && (next < 0 || wake < end_[next])) {
        now_ = wake;
        if (!startReady() || !maybeReplan()) return result_;
        continue;
      }
      // Every step that ends now ends before any starts (steps of exactly equal length end
      // together: the plan's own timing).
      now_ = end_[next];
      std::vector<int> arrived;
      for (int i = next; i < cells_->robots(); ++i) {
        if (!moving_[i] || end_[i] != now_) continue;
        moving_[i] = false;
        ++progress_[i];
        ++result_.events;
        if (progress_[i] == cells_->lastState(i)) result_.arrivals[i] = now_;
        if (tracker_) tracker_->reportProgress(i, progress_[i]);
        arrived.push_back(i);
      }
      for (int i : arrived) {
        if (collides(i)) return result_;
      }
      if (!startReady() || !maybeReplan()) return result_;
    }
    result_.time = now_;
    for (int i = 0; i < cells_->robots(); ++i) {
      if (progress_[i] < cells_->lastState(i)) {
        result_.outcome = SimulationResult::Outcome::Deadlock;
        result_.robot = i;
        result_.message = "deadlock at time " + std::to_string(now_) + ": robot " + std::to_string(i) +
                          " stands at state " + std::to_string(progress_[i]) + " of " +
                          std::to_string(cells_->lastState(i)) + ", nobody moves";
        return result_;
      }
    }
    return result_;
  }

 private:
  bool held(int i) const {
    for (const Hold& h : holds_) {
      if (h.robot == i && h.from <= now_ && now_ < h.until) return true;
    }
    return false;
  }

  // Asks the hook whether to switch plans; on a switch, checks every robot on the new plan's
  // cells and starts what it opens. False on a collision.
  bool maybeReplan() {
    if (!replan_ || !tracker_) return true;
    ExecutionSnapshot snapshot;
    snapshot.time = now_;
    snapshot.cells = cells_;
    snapshot.tracker = &*tracker_;
    snapshot.moving = moving_;
    for (int i = 0; i < cells_->robots(); ++i) snapshot.held.push_back(held(i));
    std::optional<SimulatedReplan> next = replan_(snapshot);
    if (!next) return true;
    owned_ = std::move(*next);
    cells_ = owned_.cells.get();
    plan_ = *owned_.plan;
    for (std::size_t i = 0; i < owned_.progress.size(); ++i) {
      if (owned_.progress[i] == progress_[i]) continue;
      progress_[i] = owned_.progress[i];  // a robot moved off its path: at rest where it stands
      moving_[i] = false;
    }
    tracker_.emplace(plan_, owned_.dependencies, progress_);
    for (int i = 0; i < cells_->robots(); ++i) {
      if (collides(i)) return false;
    }
    return startReady();
  }

  // Starts every step now open, until none is; false on a collision.
  bool startReady() {
    for (bool changed = true; changed;) {
      changed = false;
      for (int i = 0; i < cells_->robots(); ++i) {
        if (moving_[i] || progress_[i] >= cells_->lastState(i) || held(i)) continue;
        if (tracker_) {
          const int released = tracker_->releasedUpTo(i);
          while (progress_[i] < released && !cells_->isMove(i, progress_[i])) {
            tracker_->reportProgress(i, ++progress_[i]);  // waits pass at once
            if (progress_[i] == cells_->lastState(i)) result_.arrivals[i] = now_;
            changed = true;
          }
          if (progress_[i] == released) continue;
        }
        moving_[i] = true;
        end_[i] = now_ + duration();
        changed = true;
        if (collides(i)) return false;
      }
    }
    return true;
  }

  double duration() {
    double d = 1.0 + delays_.slowdown * rng_.uniform01();
    if (rng_.uniform01() < delays_.stop_probability) d += delays_.max_stop * rng_.uniform01();
    return d;
  }

  PlacedCells occupied(int i) const {
    return moving_[i] ? cells_->during(i, progress_[i]) : cells_->atRest(i, progress_[i]);
  }

  // Robot i against every other robot, as they stand now; records the first overlap.
  bool collides(int i) {
    const PlacedCells mine = occupied(i);
    for (int j = 0; j < cells_->robots(); ++j) {
      if (j == i || !overlap(mine, occupied(j))) continue;
      result_.outcome = SimulationResult::Outcome::Collision;
      result_.robot = i;
      result_.other = j;
      result_.time = now_;
      result_.message = "collision at time " + std::to_string(now_) + ": robot " + std::to_string(i) + " " +
                        describe(i) + " and robot " + std::to_string(j) + " " + describe(j);
      return true;
    }
    return false;
  }

  std::string describe(int i) const {
    const Path& p = cells_->path(i);
    return moving_[i] ? "doing step " + std::to_string(progress_[i]) + " from " + toString(stateAt(p, progress_[i]))
                      : "at rest at state " + std::to_string(progress_[i]) + " " + toString(stateAt(p, progress_[i]));
  }

  const PlanCells* cells_;
  SimulatedReplan owned_;  ///< the plan switched to last, if any
  DelayModel delays_;
  Rng rng_;
  Plan plan_;  ///< the tracker's copy of the paths
  std::optional<ExecutionTracker> tracker_;
  std::vector<int> progress_;
  std::vector<bool> moving_;
  std::vector<double> end_;
  double now_ = 0.0;
  SimulationResult result_;
  std::vector<Hold> holds_;
  ReplanHook replan_;
};

}  // namespace

SimulationResult simulateExecution(const PlanCells& cells, const StepDependencies* dependencies,
                                   const DelayModel& delays, std::uint64_t seed, const std::vector<Hold>& holds,
                                   const ReplanHook& replan) {
  return Simulation(cells, dependencies, delays, seed, holds, replan).run();
}

const char* outcomeName(SimulationResult::Outcome outcome) {
  switch (outcome) {
    case SimulationResult::Outcome::Completed:
      return "completed";
    case SimulationResult::Outcome::Collision:
      return "collision";
    case SimulationResult::Outcome::Deadlock:
      return "deadlock";
  }
  return "?";
}

}  // namespace fleet_planner
