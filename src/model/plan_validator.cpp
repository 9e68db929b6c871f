#include "fleet_planner/model/plan_validator.h"

#include "fleet_planner/model/robot_cells.h"

#include <algorithm>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/model/footprint_cells.h"

namespace fleet_planner {

namespace {

// Every cell of `set` at `origin` is on the map and free.
bool cellsFree(const GridMap& map, const CellSet& set, const GridPose& origin) {
  for (const auto& run : set.runs()) {
    for (int x = run.x0; x <= run.x1; ++x) {
      if (map.blocked(origin.x + x, origin.y + run.dy)) return false;
    }
  }
  return true;
}

// The bounding box of `set` placed at `origin`, inclusive (x0 > x1 for an empty set).
struct Box {
  int x0, y0, x1, y1;
};

Box boxOf(const CellSet& set, const GridPose& origin) {
  if (set.empty()) return {1, 1, 0, 0};
  return {origin.x + set.minX(), origin.y + set.minY(), origin.x + set.maxX(), origin.y + set.maxY()};
}

// The pairs (i < j) whose boxes share a cell, sorted: the only pairs whose sets can overlap
// (sweep and prune along x). A broad phase only: every candidate is still checked cell by cell.
std::vector<std::pair<int, int>> overlappingBoxes(const std::vector<Box>& boxes) {
  std::vector<int> order(boxes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return boxes[a].x0 < boxes[b].x0; });
  std::vector<std::pair<int, int>> pairs;
  std::vector<int> active;
  for (int k : order) {
    const Box& b = boxes[k];
    if (b.x0 > b.x1) continue;
    active.erase(std::remove_if(active.begin(), active.end(), [&](int m) { return boxes[m].x1 < b.x0; }),
                 active.end());
    for (int m : active) {
      if (boxes[m].y0 <= b.y1 && b.y0 <= boxes[m].y1) pairs.emplace_back(std::min(k, m), std::max(k, m));
    }
    active.push_back(k);
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

class Checker {
 public:
  Checker(const GridMap& map, const Instance& instance, const Plan& plan, const ActionModel& model,
          std::vector<bool> checked = {}, int from = 0)
      : map_(map), instance_(instance), plan_(plan), model_(model), checked_(std::move(checked)), from_(from) {
    if (checked_.empty()) checked_.assign(instance.robots.size(), true);
  }

  Violation run() {
    const int n = static_cast<int>(instance_.robots.size());
    if (static_cast<int>(plan_.paths.size()) != n) {
      return fail(Violation::Kind::WrongPathCount, -1, -1, -1,
                  "plan has " + std::to_string(plan_.paths.size()) + " paths for " +
                      std::to_string(n) + " robots");
    }
    for (int i = 0; i < n; ++i) {
      const Robot& r = instance_.robots[i];
      const Path& p = plan_.paths[i];
      if (p.empty()) return fail(Violation::Kind::EmptyPath, i, -1, 0, "path is empty");
      // A start or target yaw off the grid: the path turns there from or to any heading.
      auto samePlace = [](const GridPose& a, const GridPose& b) { return a.x == b.x && a.y == b.y; };
      if (r.start_yaw ? !samePlace(p.front(), r.start) : p.front() != r.start)
        return fail(Violation::Kind::WrongStart, i, -1, 0,
                    "path starts at " + toString(p.front()) + ", start is " + toString(r.start));
      if (r.target_yaw ? !samePlace(p.back(), r.target) : p.back() != r.target)
        return fail(Violation::Kind::WrongTarget, i, -1, static_cast<int>(p.size()) - 1,
                    "path ends at " + toString(p.back()) + ", target is " + toString(r.target));
      for (const GridPose& s : p) {
        if (!validHeading(s.heading))
          return fail(Violation::Kind::IllegalAction, i, -1, -1, "heading of " + toString(s) + " is not 0..3");
      }
    }
    cells_.reserve(n);
    for (const Robot& r : instance_.robots) cells_.push_back(sharedFootprintCells(r.footprint, model_.step));
    for (int i = 0; i < n; ++i) {
      motions_.push_back(std::make_unique<RobotCells>(instance_.robots[i], *cells_[i], plan_.paths[i]));
      if (!motions_[i]->shapeProblem().empty())
        return fail(Violation::Kind::IllegalAction, i, -1, -1, motions_[i]->shapeProblem());
    }

    int horizon = 0;
    for (const Path& p : plan_.paths) horizon = std::max(horizon, static_cast<int>(p.size()) - 1);
    const int first = std::min(from_, horizon);

    for (int i = 0; i < n; ++i) {
      if (!checked_[i]) continue;
      const GridPose& s = stateAt(plan_.paths[i], first);
      if (!cellsFree(map_, motions_[i]->bodyAt(first), s))
        return fail(Violation::Kind::StateInObstacle, i, -1, first,
                    "footprint at " + toString(s) + " covers a blocked or off-map cell");
    }
    if (Violation v = vertexConflicts(first); v.kind != Violation::Kind::None) return v;

    std::vector<const CellSet*> sweeps(n);
    for (int t = first; t < horizon; ++t) {
      for (int i = 0; i < n; ++i) {
        sweeps[i] = motions_[i]->sweepAt(t, model_);
        if (!checked_[i]) continue;
        const GridPose& from = stateAt(plan_.paths[i], t);
        const GridPose& to = stateAt(plan_.paths[i], t + 1);
        const auto action = motions_[i]->actionAt(t, model_);
        if (!action || sweeps[i] == nullptr)
          return fail(Violation::Kind::IllegalAction, i, -1, t,
                      "no action leads from " + toString(from) + " to " + toString(to));
        if (!cellsFree(map_, motions_[i]->bodyAt(t + 1), to))
          return fail(Violation::Kind::StateInObstacle, i, -1, t + 1,
                      "footprint at " + toString(to) + " covers a blocked or off-map cell");
        if (!cellsFree(map_, *sweeps[i], from))
          return fail(Violation::Kind::SweepInObstacle, i, -1, t,
                      std::string(actionName(*action)) + " from " + toString(from) +
                          " sweeps a blocked or off-map cell");
      }
      if (Violation v = vertexConflicts(t + 1); v.kind != Violation::Kind::None) return v;
      std::vector<Box> boxes(n);
      for (int i = 0; i < n; ++i) {
        const GridPose& a = stateAt(plan_.paths[i], t);
        boxes[i] = sweeps[i] ? boxOf(*sweeps[i], a) : Box{1, 1, 0, 0};  // an unchecked robot's illegal step: no box
      }
      for (const auto& [i, j] : overlappingBoxes(boxes)) {
        if (!checked(i, j, t)) continue;
        const GridPose& a = stateAt(plan_.paths[i], t);
        const GridPose& b = stateAt(plan_.paths[j], t);
        if (CellSet::overlap(*sweeps[i], {a.x, a.y}, *sweeps[j], {b.x, b.y}))
          return fail(Violation::Kind::TransferConflict, i, j, t,
                      std::string(actionName(*motions_[i]->actionAt(t, model_))) + " from " + toString(a) + " and " +
                          actionName(*motions_[j]->actionAt(t, model_)) + " from " + toString(b) + " sweep a common cell");
      }
    }
    return {};
  }

 private:
  bool checked(int i, int j, int t) const {
    if (!checked_[i] && !checked_[j]) return false;
    return t >= std::max(instance_.robots[i].conflicts_from, instance_.robots[j].conflicts_from);
  }

  Violation vertexConflicts(int t) {
    const int n = static_cast<int>(cells_.size());
    std::vector<Box> boxes(n);
    for (int i = 0; i < n; ++i) {
      const GridPose& a = stateAt(plan_.paths[i], t);
      boxes[i] = boxOf(motions_[i]->bodyAt(t), a);
    }
    for (const auto& [i, j] : overlappingBoxes(boxes)) {
      if (!checked(i, j, t)) continue;
      const GridPose& a = stateAt(plan_.paths[i], t);
      const GridPose& b = stateAt(plan_.paths[j], t);
      if (CellSet::overlap(motions_[i]->bodyAt(t), {a.x, a.y}, motions_[j]->bodyAt(t), {b.x, b.y}))
        return fail(Violation::Kind::VertexConflict, i, j, t,
                    "footprints at " + toString(a) + " and " + toString(b) + " overlap");
    }
    return {};
  }

  Violation fail(Violation::Kind kind, int robot, int other, int time, const std::string& what) const {
    Violation v;
    v.kind = kind;
    v.robot = robot;
    v.other = other;
    v.time = time;
    std::ostringstream out;
    out << violationName(kind);
    if (robot >= 0) out << ": robot '" << instance_.robots[robot].id << "'";
    if (other >= 0) out << " and robot '" << instance_.robots[other].id << "'";
    if (time >= 0) out << " at t=" << time;
    out << ": " << what;
    v.message = out.str();
    return v;
  }

  const GridMap& map_;
  const Instance& instance_;
  const Plan& plan_;
  const ActionModel& model_;
  std::vector<bool> checked_;  ///< robots whose paths and conflicts are checked
  int from_ = 0;               ///< the first state checked
  std::vector<std::shared_ptr<const FootprintCells>> cells_;
  std::vector<std::unique_ptr<RobotCells>> motions_;
};

}  // namespace

ValidationResult validatePlan(const GridMap& map, const Instance& instance, const Plan& plan,
                              const ActionModel& model) {
  return {Checker(map, instance, plan, model).run()};
}

ValidationResult validatePlanChanges(const GridMap& map, const Instance& instance, const Plan& plan,
                                     const ActionModel& model, const std::vector<int>& changed, int from) {
  std::vector<bool> checked(instance.robots.size(), false);
  for (int r : changed) {
    if (r >= 0 && r < static_cast<int>(checked.size())) checked[r] = true;
  }
  return {Checker(map, instance, plan, model, std::move(checked), std::max(from, 0)).run()};
}

const char* violationName(Violation::Kind kind) {
  switch (kind) {
    case Violation::Kind::None:
      return "valid";
    case Violation::Kind::WrongPathCount:
      return "wrong path count";
    case Violation::Kind::EmptyPath:
      return "empty path";
    case Violation::Kind::WrongStart:
      return "wrong start";
    case Violation::Kind::WrongTarget:
      return "wrong target";
    case Violation::Kind::StateInObstacle:
      return "state in obstacle";
    case Violation::Kind::IllegalAction:
      return "illegal action";
    case Violation::Kind::SweepInObstacle:
      return "sweep in obstacle";
    case Violation::Kind::VertexConflict:
      return "vertex conflict";
    case Violation::Kind::TransferConflict:
      return "transfer conflict";
  }
  return "?";
}

}  // namespace fleet_planner
