#pragma once
// Large robots close together on a free map and random walks of theirs: the scenes of the
// tests of the searches' lookups (contact probes, the soft path table's answers).
#include <vector>

#include "fleet_planner/solvers/search/soft_path_table.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {

// Robots of 4-11 cells across (real robots on a 5 cm map are 6-20) close together on a 40 x 40
// map, so that random walks from there meet. The small disc fits inside the others' sweeps.
inline std::vector<Robot> largeRobots() {
  const Footprint nose = Footprint::polygon({{-3.5, -3.5}, {-3.5, 3.5}, {3.5, 3.5}, {5.0, 0.0}, {3.5, -3.5}});
  return {makeRobot("disc", Footprint::circle(3.0), {14, 14, 0}, {14, 14, 0}),
          makeRobot("block", Footprint::block(-4.9, -2.9, 4.9, 2.9), {24, 14, 2}, {24, 14, 2}),
          makeRobot("nose", nose, {14, 24, 1}, {14, 24, 1}),
          makeRobot("wide", Footprint::block(-4.9, -3.4, 4.9, 3.4), {24, 24, 3}, {24, 24, 3}),
          makeRobot("small", Footprint::circle(1.5), {19, 19, 0}, {19, 19, 0})};
}

// The large robots on their 40 x 40 map with graphs of the action model `model` (a lattice
// step, backward moves), and the search space of all of them.
struct LargeRobotsOn {
  explicit LargeRobotsOn(ActionModel model)
      : w(freeMap(40, 40), largeRobots()), graphs(w.map, footprintsOf(w), model), sub(withGraphs()), space(sub) {}
  static std::vector<Footprint> footprintsOf(const World& world) {
    std::vector<Footprint> footprints;
    for (const Robot& r : world.instance.robots) footprints.push_back(r.footprint);
    return footprints;
  }
  Subproblem withGraphs() const {
    Subproblem all = allRobots(w);
    all.graphs = &graphs;
    return all;
  }
  const World w;
  const FleetGraphs graphs;
  const Subproblem sub;
  const SearchSpace space;
};

// A random state of agent a near the others: a few cells from a random pose of their walks (in
// `space`, which has every robot), any heading.
inline StateId somewhere(const SearchSpace& space, int a, const std::vector<StatePath>& walks, Rng& rng) {
  for (int tries = 0; tries < 100; ++tries) {
    const int b = static_cast<int>(rng.uniformInt(0, static_cast<std::int64_t>(walks.size()) - 1));
    const StatePath& w = walks[b];
    const GridPose p = space.graph(b).pose(w[rng.uniformInt(0, static_cast<std::int64_t>(w.size()) - 1)]);
    const int x = p.x + static_cast<int>(rng.uniformInt(-3, 3)), y = p.y + static_cast<int>(rng.uniformInt(-3, 3));
    const StateId s = space.graph(a).id({x, y, static_cast<int>(rng.uniformInt(0, kHeadings - 1))});
    if (s != kNoState && space.distance(a, s) >= 0) return s;
  }
  return space.start(a);
}

// A random walk of up to 10 steps of every agent from its start, each put in `table`.
inline std::vector<StatePath> walksInto(SoftPathTable& table, const SearchSpace& space, Rng& rng) {
  std::vector<StatePath> walks;
  for (int a = 0; a < space.numAgents(); ++a) {
    walks.push_back(randomWalk(space, a, static_cast<int>(rng.uniformInt(0, 10)), rng));
    table.insert(a, walks.back());
  }
  return walks;
}

// The pose after a move of agent a from s (its graph's successor).
inline StateId after(const SearchSpace& space, int a, StateId s, Action action) {
  StateId next = kNoState;
  space.graph(a).forEachSuccessor(s, [&](Action act, StateId n) {
    if (act == action) next = n;
  });
  return next;
}

}  // namespace fleet_planner::test
