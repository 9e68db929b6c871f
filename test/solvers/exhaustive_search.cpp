#include "exhaustive_search.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <queue>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/model/footprint_cells.h"

namespace fleet_planner::test {

namespace {

using Key = std::uint64_t;
constexpr Key kNoParent = std::numeric_limits<Key>::max();

/// Every cell of `set` placed at `pose` is on the map and free.
bool cellsFree(const GridMap& map, const CellSet& set, const GridPose& pose) {
  for (const Cell& c : set.cells()) {
    if (map.blocked(pose.x + c.x, pose.y + c.y)) return false;
  }
  return true;
}

/// One robot's legal poses (compactly numbered) and legal actions, from the map alone.
struct RobotSpace {
  std::unique_ptr<FootprintCells> cells;
  std::vector<GridPose> poses;                             ///< compact index -> pose
  std::vector<int> index;                                  ///< (y * w + x) * 4 + h -> compact or -1
  std::vector<std::vector<std::pair<Action, int>>> moves;  ///< per pose: action, next pose
  int start = -1;
  int target = -1;

  int find(const GridMap& map, const GridPose& p) const {
    if (!map.inside(p.x, p.y) || !validHeading(p.heading)) return -1;
    return index[map.index(p.x, p.y) * kHeadings + p.heading];
  }
};

RobotSpace buildSpace(const GridMap& map, const Robot& robot, const ActionModel& model) {
  RobotSpace s;
  s.cells = std::make_unique<FootprintCells>(robot.footprint);
  s.index.assign(static_cast<std::size_t>(map.numCells()) * kHeadings, -1);
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      for (int h = 0; h < kHeadings; ++h) {
        const GridPose p{x, y, h};
        if (!cellsFree(map, s.cells->body(h), p)) continue;
        s.index[map.index(x, y) * kHeadings + h] = static_cast<int>(s.poses.size());
        s.poses.push_back(p);
      }
    }
  }
  std::vector<Action> actions{Action::Wait, Action::Forward, Action::RotateCcw, Action::RotateCw};
  if (model.allow_backward) actions.push_back(Action::Backward);
  s.moves.resize(s.poses.size());
  for (std::size_t i = 0; i < s.poses.size(); ++i) {
    const GridPose& p = s.poses[i];
    for (Action a : actions) {
      const int next = s.find(map, applyAction(p, a));
      if (next < 0 || !cellsFree(map, s.cells->swept(p.heading, a), p)) continue;
      s.moves[i].push_back({a, next});
    }
  }
  s.start = s.find(map, robot.start);
  s.target = s.find(map, robot.target);
  return s;
}

struct Node {
  long long g = 0;
  Key parent = kNoParent;
  bool closed = false;
};

class Search {
 public:
  Search(const GridMap& map, const Instance& instance, long long budget, const ActionModel& model)
      : n_(static_cast<int>(instance.robots.size())), budget_(budget) {
    if (n_ < 1 || n_ > 4) throw std::invalid_argument("exhaustiveSearch: 1 to 4 robots");
    for (const Robot& r : instance.robots) spaces_.push_back(buildSpace(map, r, model));
    all_ = (1u << n_) - 1u;
  }

  ExhaustiveResult run() {
    ExhaustiveResult out;
    std::vector<int> start(n_);
    for (int i = 0; i < n_; ++i) {
      if (spaces_[i].start < 0 || spaces_[i].target < 0) return out;
      start[i] = spaces_[i].start;
    }
    for (int i = 0; i < n_; ++i)
      for (int j = i + 1; j < n_; ++j)
        if (footprintsOverlap(*spaces_[i].cells, pose(i, start[i]), *spaces_[j].cells,
                              pose(j, start[j])))
          return out;
    relaxCommits(start, 0, 0, kNoParent);
    while (!open_.empty()) {
      const auto [g, key] = open_.top();
      open_.pop();
      Node& node = nodes_[key];
      if (node.closed || node.g != g) continue;
      node.closed = true;
      std::vector<int> config;
      unsigned mask = 0;
      decode(key, config, mask);
      if (mask == all_) {
        out.soc = g;
        out.plan = reconstruct(key);
        out.states = static_cast<long long>(nodes_.size());
        return out;
      }
      expand(config, mask, g, key);
      if (static_cast<long long>(nodes_.size()) > budget_) {
        out.budget_exhausted = true;
        out.states = static_cast<long long>(nodes_.size());
        return out;
      }
    }
    out.states = static_cast<long long>(nodes_.size());
    return out;
  }

 private:
  const GridPose& pose(int robot, int compact) const { return spaces_[robot].poses[compact]; }

  Key encode(const std::vector<int>& config, unsigned mask) const {
    Key key = 0;
    for (int i = 0; i < n_; ++i) key = key * spaces_[i].poses.size() + static_cast<Key>(config[i]);
    return (key << n_) | mask;
  }

  void decode(Key key, std::vector<int>& config, unsigned& mask) const {
    mask = static_cast<unsigned>(key & all_);
    key >>= n_;
    config.assign(n_, 0);
    for (int i = n_ - 1; i >= 0; --i) {
      config[i] = static_cast<int>(key % spaces_[i].poses.size());
      key /= spaces_[i].poses.size();
    }
  }

  /// Pushes (config, mask | s) at cost g for every subset s of the uncommitted robots on target.
  void relaxCommits(const std::vector<int>& config, unsigned mask, long long g, Key parent) {
    unsigned on_target = 0;
    for (int i = 0; i < n_; ++i)
      if (!(mask >> i & 1u) && config[i] == spaces_[i].target) on_target |= 1u << i;
    for (unsigned s = on_target;; s = (s - 1) & on_target) {
      const Key key = encode(config, mask | s);
      auto it = nodes_.find(key);
      if (it == nodes_.end() || (!it->second.closed && g < it->second.g)) {
        nodes_[key] = Node{g, parent, false};
        open_.push({g, key});
      }
      if (s == 0) break;
    }
  }

  /// Enumerates every conflict-free joint step from (config, mask).
  void expand(const std::vector<int>& config, unsigned mask, long long g, Key key) {
    long long step_cost = 0;
    for (int i = 0; i < n_; ++i)
      if (!(mask >> i & 1u)) ++step_cost;
    std::vector<std::pair<Action, int>> chosen(n_);
    std::vector<int> next(n_);
    std::function<void(int)> choose = [&](int i) {
      if (i == n_) {
        for (int k = 0; k < n_; ++k) next[k] = chosen[k].second;
        relaxCommits(next, mask, g + step_cost, key);
        return;
      }
      const std::vector<std::pair<Action, int>> wait_only{{Action::Wait, config[i]}};
      const auto& options = (mask >> i & 1u) ? wait_only : spaces_[i].moves[config[i]];
      for (const auto& move : options) {
        bool ok = true;
        for (int j = 0; j < i && ok; ++j) {
          ok = !footprintsOverlap(*spaces_[i].cells, pose(i, move.second), *spaces_[j].cells,
                                  pose(j, chosen[j].second)) &&
               !sweepsOverlap(*spaces_[i].cells, pose(i, config[i]), move.first, *spaces_[j].cells,
                              pose(j, config[j]), chosen[j].first);
        }
        if (!ok) continue;
        chosen[i] = move;
        choose(i + 1);
      }
    };
    choose(0);
  }

  Plan reconstruct(Key key) const {
    std::vector<Key> chain;
    for (Key k = key; k != kNoParent; k = nodes_.at(k).parent) chain.push_back(k);
    Plan plan;
    plan.paths.assign(n_, {});
    std::vector<int> config;
    unsigned mask = 0;
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      decode(*it, config, mask);
      for (int i = 0; i < n_; ++i) plan.paths[i].push_back(pose(i, config[i]));
    }
    return plan;
  }

  int n_;
  long long budget_;
  unsigned all_ = 0;
  std::vector<RobotSpace> spaces_;
  std::unordered_map<Key, Node> nodes_;
  using Entry = std::pair<long long, Key>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open_;
};

}  // namespace

ExhaustiveResult exhaustiveSearch(const GridMap& map, const Instance& instance,
                                  long long state_budget, const ActionModel& model) {
  return Search(map, instance, state_budget, model).run();
}

long long exhaustiveOptimalSoc(const GridMap& map, const Instance& instance,
                               long long state_budget) {
  return exhaustiveSearch(map, instance, state_budget).soc;
}

}  // namespace fleet_planner::test
