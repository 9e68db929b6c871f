#pragma once
/// Collision-free low level of LA-LNS (la_lns.h): safe interval path planning for one large
/// agent around the other agents' paths in a SoftPathTable, taken as hard obstacles, and the
/// static footprints and timed paths of other subproblems.
///   Phillips, Likhachev. "SIPP: Safe Interval Path Planning for Dynamic Environments."
///   ICRA 2011.
/// A state's safe intervals are the runs of steps during which the agent can wait there; a
/// search node is a state and one of its intervals, reached at the earliest time, so a long
/// wait (for another robot to drive past) is one node, not one node per step. Moves are
/// checked with their swept cells during the departure step. Waiting is only allowed inside a
/// safe interval, which also makes every state passed through one the agent could wait in:
/// slightly conservative, never unsafe.
#include "fleet_planner/runtime/deadline.h"
#include "fleet_planner/solvers/search/soft_path_table.h"

namespace fleet_planner {

struct SafeIntervalResult {
  enum class Outcome { Found, NoPath, Expired, NodeLimit };
  Outcome outcome = Outcome::NoPath;
  StatePath path;  ///< states at t = 0, 1, ..., ending at the target, held from then on
  long long expansions = 0;
};

/// Earliest-arriving collision-free path of agent a (its own path in `others`, if any, is
/// ignored), after at most `max_expansions` expansions. Only arrivals at the target by step
/// `max_arrival` are searched: NoPath then means none arrives by then (a bound prunes the
/// search early when the caller wants only a path cheaper than one it has). With `weight` > 1
/// nodes are ordered by arrival + weight x distance: a path within the bound, found sooner,
/// not always the earliest.
SafeIntervalResult safeIntervalSearch(const SearchSpace& space, int a, const SoftPathTable& others,
                                      const Deadline& deadline, long long max_expansions,
                                      int max_arrival = SoftPathTable::kNever,
                                      double weight = 1.0);

/// The earliest step at which agent a could arrive at its target and stay there for good
/// around `others` (its own path, if there, ignored) and the timed paths of other subproblems,
/// however far it is: a lower bound on its arrival. SoftPathTable::kNever if it never can.
int earliestArrivalForGood(const SearchSpace& space, int a, const SoftPathTable& others);

/// A collision-free way of agent a home, held for good, from state `from` at step t0 (the path
/// holds the states from t0 on). When its target is free for good only from a step `ready`
/// much later than a could get there, the earliest arrival costs a search of every state it
/// could wait in before `ready`; instead a first waits where it stands, if it safely can, and
/// departs kHomeLeadSteps plus twice its distance before `ready`, arriving by kHomeLeadSteps
/// plus its distance after `ready`. Otherwise, or when that finds no way, the
/// earliest arrival (as safeIntervalSegment). Not always the earliest arrival.
SafeIntervalResult safeIntervalHome(const SearchSpace& space, int a, const SoftPathTable& others,
                                    StateId from, int t0, const Deadline& deadline,
                                    long long max_expansions);
constexpr int kHomeLeadSteps = 8;

/// A collision-free way of agent a from state `from` at step t0 to `pocket`, held for good (the
/// path holds the states from t0 on): the earliest arrival after the last step anybody in
/// `others` (or another subproblem's timed path) sweeps the pocket, departing late first as
/// safeIntervalHome does, with the pocket's lower bound of steps for the distance. NoPath if
/// the pocket is never free for good (someone ends there).
SafeIntervalResult safeIntervalPocket(const SearchSpace& space, int a, const SoftPathTable& others,
                                      StateId from, int t0, StateId pocket, const Deadline& deadline,
                                      long long max_expansions);

/// A collision-free piece of agent a's way, to splice into its path: from state `from` at step
/// t0 to state `to`, reached by step t1 and held until t1, or reached at a step t1 + d with
/// 0 < d <= max_delay (the path then holds the states at steps t0..t1 + d: d is the delay the
/// rest of the way takes on), or, with t1 == SoftPathTable::kNever, to a's target, held for
/// good (as safeIntervalSearch; the path then holds the states from t0 on). Earliest arrival.
SafeIntervalResult safeIntervalSegment(const SearchSpace& space, int a,
                                       const SoftPathTable& others, StateId from, int t0,
                                       StateId to, int t1, int max_delay,
                                       const Deadline& deadline, long long max_expansions);

}  // namespace fleet_planner
