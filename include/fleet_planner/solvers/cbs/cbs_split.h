#pragma once
/// How LA-CBS splits a conflict into two branches whose constraints no solution can violate in
/// both (la_cbs.h has the references).
///
/// - Cell split (Li et al. 2019, lifted to cells): a cell both agents cover at the conflict is
///   forbidden to one agent or the other at that time (vertex) or during that step (transfer).
/// - Target split (Li et al. ICAPS 2020, target symmetry): when one agent, A, already holds its
///   target at the conflict's time t, the branches are "A's cost exceeds t" and "A's cost is at
///   most t, so the other agent keeps off A's target footprint from t on". Every solution is in
///   exactly one branch, and neither needs the other agent to wait out A one step at a time.
#include <array>
#include <vector>

#include "fleet_planner/solvers/search/agent_conflicts.h"
#include "fleet_planner/solvers/search/agent_constraints.h"
#include "fleet_planner/solvers/search/search_space.h"

namespace fleet_planner {

/// One constraint on one agent, as a constraint-tree node stores it.
struct CbsConstraint {
  enum class Kind { CellAt, CellDuring, TargetAreaFrom, CostAbove, CostAtMost };
  Kind kind = Kind::CellAt;
  int agent = -1;
  int t = 0;
  Cell cell;       ///< CellAt, CellDuring
  int owner = -1;  ///< TargetAreaFrom: the agent whose target footprint is forbidden
};

/// Adds `c` to `constraints` (of agent c.agent). `space` must outlive `constraints`.
void applyConstraint(const SearchSpace& space, const CbsConstraint& c, AgentConstraints& constraints);

/// One branch of a split: its constraints and the one agent whose path they invalidate.
struct CbsBranch {
  std::vector<CbsConstraint> constraints;
  int replan = -1;
};

/// Path cost: the time from which the path holds its last state for good.
int pathCost(const StatePath& path);

/// Agent `agent` holds its target for good from time t on in its path (its cost is at most t).
bool holdsTargetAt(const SearchSpace& space, const StatePath& path, int agent, int t);

/// The earliest target conflict of each agent pair among `paths` (one where an agent already
/// holds its target: splitConflict() splits it on that agent's cost), in the order of
/// firstConflict(). The earliest conflict of a pair is often not one: two robots meet on the
/// way, and only later does one of them park in the other's way.
std::vector<AgentConflict> targetConflicts(const SearchSpace& space, const std::vector<StatePath>& paths);

/// The two branches for `conflict` among `paths`: the target split if one of the agents holds
/// its target from the conflict's time on (agent a checked first), else the cell split (a's
/// branch first). In each branch the replanned agent's current path violates its constraints.
std::array<CbsBranch, 2> splitConflict(const SearchSpace& space, const std::vector<StatePath>& paths,
                                       const AgentConflict& conflict);

}  // namespace fleet_planner
