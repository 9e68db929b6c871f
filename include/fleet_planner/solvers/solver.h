#pragma once
/// The interface every LA-MAPF backend implements (paper: "Solving and combining"). A backend
/// plans one subproblem: some robots of an instance, with the footprints of other robots as
/// static obstacles and, for serial backends, the timed plans of other robots as moving
/// obstacles.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"
#include "fleet_planner/solvers/backend_parameters.h"

namespace fleet_planner {

/// A robot of the instance standing still at a pose for the whole solve.
struct StaticFootprint {
  int robot = -1;  ///< instance index (its footprint is used)
  GridPose pose;
};

/// A robot of the instance following a timed path, then staying at its last pose forever.
struct MovingObstacle {
  int robot = -1;  ///< instance index (its footprint is used)
  Path path;
  /// Steps 0..held_through of the path are taken from step 0 on, not only when the path does
  /// them: a robot already allowed to drive them may be anywhere on them until then (an
  /// executing robot's released steps, execution/replanning.h). -1: none.
  int held_through = -1;
  /// The held steps are taken for good, not only until the path does them (a robot that may
  /// stand still on them for long: a fault, a person in the way).
  bool held_for_good = false;
  /// The path's first step turns in place from this yaw, its last step to this one (as a
  /// Robot's, robot_cells.h): an executing robot's path cut from a full plan.
  std::optional<double> start_yaw = std::nullopt, target_yaw = std::nullopt;
  int start_turn = 0;  ///< the step of the turn from start_yaw (Robot::start_turn)
};

struct Subproblem {
  const Instance* instance = nullptr;
  const FleetGraphs* graphs = nullptr;   ///< graphs of every robot of the instance
  std::vector<int> robots;               ///< instance indices of the robots to plan
  std::vector<StaticFootprint> blocked;  ///< cells covered by these footprints are blocked
  std::vector<MovingObstacle> moving;    ///< serial backends avoid these; others reject them
  /// Robots of `robots` planned from and back to the pose given here instead of from their start
  /// to their target: robots of other subproblems standing in the way, which may step aside
  /// and come back. Entries for robots not in `robots` are ignored.
  std::vector<StaticFootprint> returning;
  Deadline deadline;
  std::uint64_t seed = 0;
  /// Low-level expansions the backend may spend before answering TIMEOUT (-1: no limit).
  /// Backends that count expansions honour it; unlike a deadline, it gives the same outcome on
  /// every machine.
  long long max_expansions = -1;
  /// Asked by a backend whose search is stuck: true if the caller has something else to try
  /// (robots of other subproblems may step aside), and the backend may answer TIMEOUT now
  /// rather than spend the deadline. Empty: no. Backends that repair a plan ask it (LA-LNS: after
  /// a stall with every agent replanned, a count of repairs, so the outcome does not depend on
  /// the machine). A question, not a flag: the answer costs a search per robot.
  std::function<bool()> may_give_up;
  /// The caller has another way to plan these robots if this search stalls (the planner: the
  /// fleet on a coarser lattice), whoever stands near: a backend that repairs a plan may answer
  /// TIMEOUT once it stops making progress (LA-LNS: `end_stall_repairs` repairs in a row
  /// without a new lowest number of colliding pairs) rather than spend the deadline. Unlike
  /// may_give_up, it leaves the backend's proofs as they are.
  bool ends_when_stalled = false;
  /// Threads the backend may use for this subproblem (LA-LNS: its parking plans' orders at
  /// once); the answer does not depend on it.
  int threads = 1;
};

/// ResourceLimit: the deadline's memory guard tripped, or a search's tables would not fit in
/// max_memory_mb (resource_limits.h); the reason names the limit. InternalError: a plan that
/// fails the independent validator (a defect of this package, never an input problem).
enum class SolveStatus { Success, Timeout, Infeasible, Cancelled, InvalidInput, ResourceLimit, InternalError };

/// "SUCCESS", "TIMEOUT", "INFEASIBLE", "CANCELLED", "INVALID_INPUT", "RESOURCE_LIMIT",
/// "INTERNAL_ERROR".
const char* statusName(SolveStatus status);

struct SolveStats {
  double time_s = 0.0;
  long long high_level_nodes = 0;
  long long low_level_expansions = 0;
  double peak_memory_mb = -1.0;  ///< the search's own estimate; -1 if unknown
  /// A proven lower bound on the sum of costs (in steps) of the subproblem's robots in any plan
  /// without conflicts among them (LA-CBS's constraint tree); -1 if the backend proves none.
  long long lower_bound = -1;
};

struct SolveResult {
  SolveStatus status = SolveStatus::InvalidInput;
  std::string reason;       ///< human-readable, names the robot where one is to blame
  std::vector<Path> paths;  ///< on success: one per Subproblem::robots entry, same order
  SolveStats stats;
  /// On failure, the robots it is about (instance indices), most suspect first: a group proven
  /// unable to reach its targets, or the robots of the colliding pairs left. May be empty.
  std::vector<int> culprits;
  /// On success: the plan a search had in hand when a limit stopped it (LA-CBS's `anytime`),
  /// valid but not the search's own answer (not proven optimal); a caller with another backend
  /// may try that one and keep the cheaper plan.
  bool stopped_early = false;
  bool success() const { return status == SolveStatus::Success; }
};

class Solver {
 public:
  virtual ~Solver() = default;
  /// The registry name ("la_cbs", "la_lacam").
  virtual std::string name() const = 0;
  /// Serial backends plan around MovingObstacle paths; parallel ones only take static footprints.
  virtual bool avoidsMovingObstacles() const = 0;
  /// Sets the backend's options by name (backend_parameters.h). Throws InvalidInput naming the
  /// backend and the option for an unknown name or a value out of range, listing the known
  /// names; the options are unchanged then. A backend without options accepts only none.
  virtual void configure(const BackendOptionValues& values);
  /// Plans the subproblem. Never throws for planning outcomes; returns within ~50 ms of the
  /// deadline; same input and seed give the same result.
  virtual SolveResult solve(const Subproblem& problem) = 0;
};

}  // namespace fleet_planner
