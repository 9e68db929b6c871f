#pragma once
/// Fewer cells to look up when asking which other robots a sweep meets.
///
/// Let T be any set of cells that is 4-connected and contains a `side` x `side` square. If T
/// meets a set S, then T meets S's probe: the cells of S with a 4-neighbour outside S, and the
/// cells of S on a grid of pitch `side`. Either T has cells inside and outside S, and a
/// 4-path within T crosses S's border at a cell of the probe; or T lies inside S, and its square
/// holds a cell of the grid (any `side` consecutive columns hold one column of the grid, and the
/// same for rows). The robots' bodies and sweeps are such sets, so a lookup per cell of a
/// large robot's sweep can read only its probe: for a body of 18 x 12 cells, 58 cells of 216.
#include "fleet_planner/model/cell_set.h"

namespace fleet_planner {

/// The probe of `set` for sets that are 4-connected and hold a `side` x `side` square
/// (side >= 1; side 1 gives `set` itself).
CellSet contactProbe(const CellSet& set, int side);

/// The largest k such that `set` holds a k x k square of cells (0 when empty).
int largestSquare(const CellSet& set);

/// True when every cell of `set` can be reached from every other through 4-neighbours in it
/// (an empty set too).
bool fourConnected(const CellSet& set);

}  // namespace fleet_planner
