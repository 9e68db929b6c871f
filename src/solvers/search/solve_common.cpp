#include "fleet_planner/solvers/search/solve_common.h"

#include <chrono>
#include <exception>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/runtime/resource_limits.h"

namespace fleet_planner {

namespace {

SolveResult make(SolveStatus status, std::string reason) { return failedResult(status, std::move(reason)); }

// Two agents whose starts, or whose targets, overlap can never be solved.
std::string overlapProblem(const SearchSpace& space) {
  const int n = space.numAgents();
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      const auto pose = [&](int agent, StateId s) { return space.graph(agent).pose(s); };
      if (footprintsOverlap(space.cells(a), pose(a, space.start(a)), space.cells(b), pose(b, space.start(b))))
        return space.label(a) + " and " + space.label(b) + " overlap at their starts";
      if (footprintsOverlap(space.cells(a), pose(a, space.target(a)), space.cells(b), pose(b, space.target(b))))
        return space.label(a) + " and " + space.label(b) + " overlap at their targets";
    }
  }
  return "";
}

}  // namespace

SolveResult solveWith(const Subproblem& problem, bool moving_allowed,
                      const std::function<SolveResult(const SearchSpace&, SolveStats&)>& search) {
  const auto t0 = std::chrono::steady_clock::now();
  SolveResult result;
  try {
    if (!moving_allowed && !problem.moving.empty()) {
      result = make(SolveStatus::InvalidInput, "this backend cannot plan around moving obstacles (timed paths)");
    } else if (problem.deadline.cancelled()) {
      result = make(SolveStatus::Cancelled, "cancelled");
    } else if (problem.deadline.expired()) {  // before the search space, which takes time to build
      result = make(SolveStatus::Timeout, "deadline passed before the search started");
    } else {
      const SearchSpace space(problem);
      SolveStats stats;
      if (!space.problem().empty()) {
        result = make(SolveStatus::Infeasible, space.problem());
      } else if (space.stopped()) {
        result = make(problem.deadline.cancelled() ? SolveStatus::Cancelled : SolveStatus::Timeout,
                      "deadline passed while the distance tables were built");
      } else if (std::string overlap = overlapProblem(space); !overlap.empty()) {
        result = make(SolveStatus::Infeasible, overlap);
      } else if (problem.deadline.expired()) {
        result = make(problem.deadline.cancelled() ? SolveStatus::Cancelled : SolveStatus::Timeout,
                      "deadline passed before the search started");
      } else if (space.numAgents() == 0) {
        result = make(SolveStatus::Success, "");
      } else {
        result = search(space, stats);
      }
      result.stats = stats;
    }
  } catch (const ResourceLimitError& e) {
    result = make(SolveStatus::ResourceLimit, e.what());
  } catch (const InputError& e) {
    result = make(SolveStatus::InvalidInput, e.what());
  } catch (const std::bad_alloc&) {
    result = make(SolveStatus::ResourceLimit, "out of memory (an allocation failed)");
  }
  // A search stopped by the memory guard says "time limit reached" or names its own budget:
  // report the limit that stopped it.
  if (!result.success() && result.status != SolveStatus::ResourceLimit && problem.deadline.outOfMemory()) {
    result.status = SolveStatus::ResourceLimit;
    result.reason = problem.deadline.memoryGuard()->reason();
  }
  result.stats.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

SolveResult failedResult(SolveStatus status, std::string reason) {
  SolveResult r;
  r.status = status;
  r.reason = std::move(reason);
  return r;
}

std::vector<StatePath> toStatePaths(const SearchSpace& space, const std::vector<int>& agents,
                                    const std::vector<Path>& paths) {
  std::vector<StatePath> out(agents.size());
  for (std::size_t k = 0; k < agents.size(); ++k) {
    for (const GridPose& p : paths[k]) out[k].push_back(space.graph(agents[k]).id(p));
  }
  return out;
}

std::vector<Path> toPosePaths(const SearchSpace& space, const std::vector<StatePath>& paths) {
  std::vector<Path> out(paths.size());
  for (std::size_t a = 0; a < paths.size(); ++a) {
    StatePath p = paths[a];
    while (p.size() > 1 && p[p.size() - 2] == p.back()) p.pop_back();
    for (StateId s : p) out[a].push_back(space.graph(static_cast<int>(a)).pose(s));
  }
  return out;
}

}  // namespace fleet_planner
