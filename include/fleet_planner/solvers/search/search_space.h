#pragma once
/// The world as one subproblem sees it, shared by the backends: each agent's state graph
/// restricted by the static footprints of other subproblems, the exact distance from every
/// state to the agent's target in that restricted graph (the low-level heuristic, computed once
/// per subproblem), and the reservation table of moving obstacles.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "fleet_planner/model/obstacle_index.h"
#include "fleet_planner/solvers/search/distance_table.h"
#include "fleet_planner/solvers/search/reservation_table.h"
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

class SearchSpace {
 public:
  /// Throws InvalidInput for a malformed subproblem (missing instance or graphs, a robot index
  /// out of range or repeated). Unsolvable robots are reported by problem(), not thrown.
  /// With a memory guard on the deadline, throws ResourceLimitError (max_memory_mb) if the
  /// distance tables would not fit, before allocating them. The tables are built until the
  /// subproblem's deadline: if it passes first, stopped() is true and the space is unusable.
  explicit SearchSpace(const Subproblem& problem) : SearchSpace(problem, true) {}
  /// Without `distances`, no agent's table is built (nor its target's reachability checked):
  /// buildDistances() builds those that will be searched, for a caller that searches a few
  /// agents of many (plan refinement), and distance() must not be asked of the others.
  SearchSpace(const Subproblem& problem, bool distances);
  /// Builds agent a's distance table; false if the deadline passed first (a has none then).
  bool buildDistances(int a, const Deadline& deadline);
  /// Frees agent a's distance table.
  void dropDistances(int a) { distances_[a] = DistanceTable(); }

  int numAgents() const { return static_cast<int>(robots_.size()); }
  /// Instance index of agent a.
  int robot(int a) const { return robots_[a]; }
  const StateGraph& graph(int a) const { return graphs_->graph(robots_[a]); }
  const FootprintCells& cells(int a) const { return graphs_->cells(robots_[a]); }
  StateId start(int a) const { return starts_[a]; }
  StateId target(int a) const { return targets_[a]; }
  /// "robot '<id>'" for messages.
  std::string label(int a) const;

  /// Agent a may do `action` from s: the graph has the edge and it sweeps no blocked footprint.
  bool allows(int a, StateId s, Action action) const {
    const StateGraph& g = graph(a);
    if (!g.allows(s, action)) return false;
    if (!has_static_) return true;
    const GridPose p = g.pose(s);
    return !static_cells_->blocked(cells(a).swept(p.heading, action), {p.x, p.y});
  }
  /// Steps from s to agent a's target in the restricted graph; -1 if unreachable.
  int distance(int a, StateId s) const { return distances_[a][s]; }
  const ReservationTable& reservations() const { return reservations_; }
  /// The contact probe (contact_probe.h) of agent a's sweep doing `action` from `heading`: it
  /// meets every body or sweep of an agent and every reservation that the sweep meets, so
  /// lookups per cell may read it instead of the sweep.
  const CellSet& probe(int a, int heading, Action action) const {
    return lookups_[a]->probes[heading][static_cast<int>(action)];
  }

  /// The cells of agent a's sweep doing the move `action` from `heading` that lie outside its
  /// body before and after the move. The sweep meets a cell set iff the body before, the body
  /// after or these cells do, so a lookup may read the two bodies' answers and these few cells
  /// instead of the sweep's probe: a straight move has none or a few. Null for Wait, when the
  /// sweep does not hold both bodies, and when these cells are not fewer than half the probe
  /// (a block's turn sweeps arcs at its corners).
  struct MoveExtra {
    bool decomposes = false;
    CellSet cells;
  };
  const CellSet* moveExtra(int a, int heading, Action action) const {
    const MoveExtra& e = lookups_[a]->extras[heading][static_cast<int>(action)];
    return e.decomposes ? &e.cells : nullptr;
  }

  /// The first heading at which agent a's body and its wait's sweep are the cells they are at
  /// `heading` (a disc: 0 for every heading; a block symmetric about its centre: the same for
  /// opposite headings): waiting there meets what waiting at `heading` meets.
  int sameWaitHeading(int a, int heading) const { return lookups_[a]->same_wait[heading]; }
  /// Agent a's `turn` (RotateCcw or RotateCw) from `heading` sweeps the cells that the opposite
  /// turn back from the heading it ends at sweeps (they cover the same angles): what one meets,
  /// the other meets.
  bool turnsBackAlike(int a, int heading, Action turn) const {
    return lookups_[a]->turns_back_alike[heading][turn == Action::RotateCw ? 1 : 0];
  }

  /// Empty if every agent has a valid start and target connected in its restricted graph;
  /// otherwise why not, naming the first such robot.
  const std::string& problem() const { return problem_; }
  /// The deadline passed before every distance table was built (problem() is then only what
  /// was found until then).
  bool stopped() const { return stopped_; }

 private:
  // Builds lookups_ (after reservations_).
  void makeLookups();
  // Why agent a's start or target is not a valid free state; empty if both are.
  std::string endpointProblem(int a) const;

  const Instance* instance_;
  const FleetGraphs* graphs_;
  std::vector<int> robots_;
  std::vector<StateId> starts_, targets_;
  bool has_static_ = false;
  std::unique_ptr<ObstacleIndex> static_cells_;
  std::vector<DistanceTable> distances_;
  ReservationTable reservations_;
  // What an agent's cells give the lookups, per heading (and action): probes, moves' extra
  // cells, the heading whose wait is the same, the turns that their opposite turn back matches.
  struct Lookups {
    std::array<std::array<CellSet, kActions>, kHeadings> probes;
    std::array<std::array<MoveExtra, kActions>, kHeadings> extras;
    std::array<int, kHeadings> same_wait;
    std::array<std::array<bool, 2>, kHeadings> turns_back_alike;  // [heading][RotateCcw, RotateCw]
  };
  std::vector<std::shared_ptr<const Lookups>> lookups_;  // agents with the same cells share them
  std::string problem_;
  bool stopped_ = false;
};

}  // namespace fleet_planner
