// LA-CBS conflict splitting; see cbs_split.h for the references.
#include "fleet_planner/solvers/cbs/cbs_split.h"

namespace fleet_planner {

void applyConstraint(const SearchSpace& space, const CbsConstraint& c, AgentConstraints& constraints) {
  switch (c.kind) {
    case CbsConstraint::Kind::CellAt:
      constraints.forbidCellAt(c.cell, c.t);
      break;
    case CbsConstraint::Kind::CellDuring:
      constraints.forbidCellDuring(c.cell, c.t);
      break;
    case CbsConstraint::Kind::TargetAreaFrom: {
      const GridPose p = space.graph(c.owner).pose(space.target(c.owner));
      constraints.forbidAreaFrom(space.cells(c.owner).body(p.heading), {p.x, p.y}, c.t);
      break;
    }
    case CbsConstraint::Kind::CostAbove:
      constraints.requireCostAbove(c.t);
      break;
    case CbsConstraint::Kind::CostAtMost:
      constraints.requireCostAtMost(c.t);
      break;
  }
}

int pathCost(const StatePath& path) {
  int t = static_cast<int>(path.size()) - 1;
  while (t > 0 && path[t - 1] == path.back()) --t;
  return t;
}

bool holdsTargetAt(const SearchSpace& space, const StatePath& path, int agent, int t) {
  return pathCost(path) <= t && space.target(agent) == path.back();
}

std::vector<AgentConflict> targetConflicts(const SearchSpace& space, const std::vector<StatePath>& paths) {
  return earliestConflictPerPair(space, paths, static_cast<int>(paths.size() * paths.size()),
                                 [&](const AgentConflict& c) {
                                   return holdsTargetAt(space, paths[c.a], c.a, c.t) ||
                                          holdsTargetAt(space, paths[c.b], c.b, c.t);
                                 });
}

std::array<CbsBranch, 2> splitConflict(const SearchSpace& space, const std::vector<StatePath>& paths,
                                       const AgentConflict& conflict) {
  using Kind = CbsConstraint::Kind;
  std::array<CbsBranch, 2> branches;
  // The conflict's time t is a time (vertex) or the step t -> t + 1 (transfer); either way an
  // agent whose cost is at most t stands on its target footprint throughout.
  for (const int holder : {conflict.a, conflict.b}) {
    if (!holdsTargetAt(space, paths[holder], holder, conflict.t)) continue;
    const int other = holder == conflict.a ? conflict.b : conflict.a;
    branches[0].replan = holder;
    branches[0].constraints = {{Kind::CostAbove, holder, conflict.t, {}, -1}};
    branches[1].replan = other;
    branches[1].constraints = {{Kind::CostAtMost, holder, conflict.t, {}, -1},
                               {Kind::TargetAreaFrom, other, conflict.t, {}, holder}};
    return branches;
  }
  const Kind kind = conflict.kind == AgentConflict::Kind::Vertex ? Kind::CellAt : Kind::CellDuring;
  for (int side = 0; side < 2; ++side) {
    const int agent = side == 0 ? conflict.a : conflict.b;
    branches[side].replan = agent;
    branches[side].constraints = {{kind, agent, conflict.t, conflict.cell, -1}};
  }
  return branches;
}

}  // namespace fleet_planner
