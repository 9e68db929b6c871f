#pragma once
// The open list of LA-CBS's constraint tree (la_cbs.cpp). Weight 1: best-first by f (a lower
// bound on any plan below the node), then fewer conflicts, then lower cost. Weight w > 1 (ECBS's
// high level, Barer, Sharon, Stern, Felner, SoCS 2014): among the open nodes whose cost is at
// most w times the least open f, fewest conflicts first, then lower cost; the least-f node
// itself when none qualifies. `Node` has the fields f, cost and conflicts.
#include <cstddef>
#include <queue>
#include <vector>

namespace fleet_planner {

template <class Node>
class TreeFrontier {
 public:
  TreeFrontier(const std::vector<Node>& nodes, double weight)
      : weight_(weight), by_f_(ByF{&nodes}), pending_(ByCost{&nodes}), focal_(ByConflicts{&nodes}), nodes_(nodes) {}

  void push(int id) {
    by_f_.push(id);
    if (weight_ > 1.0) pending_.push(id);
  }

  /// The next node to expand, or -1 when none is left. Each node is handed out once.
  int pop() {
    while (!by_f_.empty() && taken(by_f_.top())) by_f_.pop();
    if (by_f_.empty()) return -1;
    int id = by_f_.top();
    least_f_ = nodes_[id].f;
    if (weight_ > 1.0) {
      const double bound = weight_ * static_cast<double>(least_f_);
      while (!pending_.empty() && static_cast<double>(nodes_[pending_.top()].cost) <= bound) {
        focal_.push(pending_.top());
        pending_.pop();
      }
      while (!focal_.empty() && taken(focal_.top())) focal_.pop();
      if (!focal_.empty()) id = focal_.top();
    }
    if (taken_.size() <= static_cast<std::size_t>(id)) taken_.resize(nodes_.size(), 0);
    taken_[id] = 1;
    return id;
  }

  /// The least f of the open nodes at the last pop: a lower bound on the optimum.
  long long leastF() const { return least_f_; }

 private:
  bool taken(int id) const { return static_cast<std::size_t>(id) < taken_.size() && taken_[id]; }

  struct ByF {
    const std::vector<Node>* nodes;
    bool operator()(int x, int y) const {
      const Node &a = (*nodes)[x], &b = (*nodes)[y];
      if (a.f != b.f) return a.f > b.f;
      if (a.conflicts != b.conflicts) return a.conflicts > b.conflicts;
      if (a.cost != b.cost) return a.cost > b.cost;
      return x > y;
    }
  };
  struct ByCost {
    const std::vector<Node>* nodes;
    bool operator()(int x, int y) const {
      const Node &a = (*nodes)[x], &b = (*nodes)[y];
      return a.cost != b.cost ? a.cost > b.cost : x > y;
    }
  };
  struct ByConflicts {
    const std::vector<Node>* nodes;
    bool operator()(int x, int y) const {
      const Node &a = (*nodes)[x], &b = (*nodes)[y];
      if (a.conflicts != b.conflicts) return a.conflicts > b.conflicts;
      if (a.cost != b.cost) return a.cost > b.cost;
      return x > y;
    }
  };

  double weight_;
  std::priority_queue<int, std::vector<int>, ByF> by_f_;
  std::priority_queue<int, std::vector<int>, ByCost> pending_;
  std::priority_queue<int, std::vector<int>, ByConflicts> focal_;
  std::vector<char> taken_;
  const std::vector<Node>& nodes_;
  long long least_f_ = 0;
};

}  // namespace fleet_planner
