#pragma once
// The open list of LA-CBS's constraint tree (la_cbs.cpp), a FocalList (focal_list.h). Weight 1:
// best-first by f (a lower bound on any plan below the node), then fewer conflicts, then lower
// cost. Weight w > 1 (ECBS's high level, Barer, Sharon, Stern, Felner, SoCS 2014): among the open
// nodes whose cost is at most w times the least open f, fewest conflicts first, then lower cost;
// the least-f node itself when none qualifies. `Node` has the fields f, cost and conflicts.
#include <vector>

#include "fleet_planner/solvers/search/focal_list.h"

namespace fleet_planner {

template <class Node>
struct TreeOrders {
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
  struct ByConflicts {
    const std::vector<Node>* nodes;
    bool operator()(int x, int y) const {
      const Node &a = (*nodes)[x], &b = (*nodes)[y];
      if (a.conflicts != b.conflicts) return a.conflicts > b.conflicts;
      if (a.cost != b.cost) return a.cost > b.cost;
      return x > y;
    }
  };
  struct Cost {
    long long operator()(const Node& n) const { return n.cost; }
  };
};

template <class Node>
using TreeFrontier = FocalList<Node, typename TreeOrders<Node>::ByF, typename TreeOrders<Node>::ByConflicts,
                               typename TreeOrders<Node>::Cost>;

}  // namespace fleet_planner
