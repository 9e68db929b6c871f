#pragma once
/// The open list of a best-first search whose nodes live in a vector (handed around by index),
/// with an optional focal list (Pearl and Kim 1982; ECBS, Barer et al. 2014, at both levels).
///
/// Weight 1: `Order`'s best node first. Weight w > 1: among the open nodes whose `Admit` key is
/// at most w times the least open f, `Focal`'s best first (the least-f node itself if none
/// qualifies). `Order` and `Focal` are "worse than" orders for std::priority_queue, `Admit` maps a
/// node to its key; each is a struct holding `const std::vector<Node>* nodes` (Admit: a
/// functor on a node). Node has an integer field `f`, a lower bound.
#include <cstddef>
#include <queue>
#include <vector>

namespace fleet_planner {

template <class Node, class Order, class Focal, class Admit>
class FocalList {
 public:
  FocalList(const std::vector<Node>& nodes, double weight)
      : weight_(weight), open_(Order{&nodes}), pending_(ByAdmission{&nodes}), focal_(Focal{&nodes}), nodes_(nodes) {}

  void push(int i) {
    open_.push(i);
    if (weight_ > 1.0) pending_.push(i);
  }

  /// The next node, or -1 when none is left. With a weight above 1 each node is handed out
  /// once and `dead(i)` drops nodes that are no longer wanted; with weight 1 the caller skips
  /// those itself.
  template <class Dead>
  int pop(Dead dead) {
    if (weight_ <= 1.0) {
      if (open_.empty()) return -1;
      const int i = open_.top();
      open_.pop();
      least_f_ = nodes_[i].f;
      return i;
    }
    auto gone = [&](int i) { return (static_cast<std::size_t>(i) < taken_.size() && taken_[i]) || dead(i); };
    while (!open_.empty() && gone(open_.top())) open_.pop();
    if (open_.empty()) return -1;
    least_f_ = nodes_[open_.top()].f;
    const double bound = weight_ * static_cast<double>(least_f_);
    while (!pending_.empty() && static_cast<double>(Admit{}(nodes_[pending_.top()])) <= bound) {
      focal_.push(pending_.top());
      pending_.pop();
    }
    while (!focal_.empty() && gone(focal_.top())) focal_.pop();
    int i = open_.top();
    if (!focal_.empty()) {
      i = focal_.top();
      focal_.pop();
    }
    if (taken_.size() <= static_cast<std::size_t>(i)) taken_.resize(nodes_.size(), 0);
    taken_[i] = 1;
    return i;
  }
  int pop() {
    return pop([](int) { return false; });
  }

  /// The least f of the open nodes at the last pop: a lower bound on what is left to find.
  long long leastF() const { return least_f_; }

 private:
  struct ByAdmission {
    const std::vector<Node>* nodes;
    bool operator()(int x, int y) const {
      const auto a = Admit{}((*nodes)[x]), b = Admit{}((*nodes)[y]);
      return a != b ? a > b : x > y;
    }
  };

  double weight_;
  std::priority_queue<int, std::vector<int>, Order> open_;
  std::priority_queue<int, std::vector<int>, ByAdmission> pending_;
  std::priority_queue<int, std::vector<int>, Focal> focal_;
  std::vector<char> taken_;
  const std::vector<Node>& nodes_;
  long long least_f_ = 0;
};

}  // namespace fleet_planner
