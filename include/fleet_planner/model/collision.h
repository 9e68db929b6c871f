#pragma once
/// Robot-robot conflicts in one time step (paper: Preliminaries, vertex and transfer conflicts,
/// after Li et al. 2019). A vertex conflict: the footprints at the same time overlap. A transfer
/// conflict: the cells swept during the same step overlap; a waiting robot sweeps its footprint.
#include "fleet_planner/model/action.h"
#include "fleet_planner/model/footprint_cells.h"
#include "fleet_planner/model/types.h"

namespace fleet_planner {

/// Robot A at pose `a` and robot B at pose `b` cover a common cell.
inline bool footprintsOverlap(const FootprintCells& A, const GridPose& a, const FootprintCells& B,
                              const GridPose& b) {
  return CellSet::overlap(A.body(a.heading), {a.x, a.y}, B.body(b.heading), {b.x, b.y});
}

/// Robot A doing `action_a` from `a` and robot B doing `action_b` from `b` in the same step
/// sweep a common cell.
inline bool sweepsOverlap(const FootprintCells& A, const GridPose& a, Action action_a,
                          const FootprintCells& B, const GridPose& b, Action action_b) {
  return CellSet::overlap(A.swept(a.heading, action_a), {a.x, a.y}, B.swept(b.heading, action_b),
                          {b.x, b.y});
}

}  // namespace fleet_planner
