#pragma once
#include <vector>

namespace fleet_planner {

/// Open-list order of the searches that count collisions (soft_path_search.cpp,
/// joint_path_search.cpp): true when node x comes after node y. Lowest f first, then fewest
/// collisions, then the deeper node (more steps), then the older one, so the order is total and
/// the search deterministic. Node needs f, collisions and steps.
template <class Node>
struct SoftOrder {
  const std::vector<Node>* nodes;
  bool operator()(int x, int y) const {
    const Node &p = (*nodes)[x], &q = (*nodes)[y];
    if (p.f != q.f) return p.f > q.f;
    if (p.collisions != q.collisions) return p.collisions > q.collisions;
    if (p.steps != q.steps) return p.steps < q.steps;
    return x > y;
  }
};

}  // namespace fleet_planner
