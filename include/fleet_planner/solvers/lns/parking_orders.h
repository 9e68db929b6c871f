#pragma once
/// The orders in which LA-LNS's parking plan (parking_plan.h) drives the robots of a packed
/// subproblem home. No order of turns suits every fleet, and which one does cannot be told
/// beforehand, so several are made and fastestParkingPlan keeps one:
///   1. longest way first (the order given): robots that go a long way make room early; a
///      robot whose target shuts another robot in or out (parking_precedence.h) comes after
///      it, the rest of the order kept;
///   2. shortest way first: robots near home are out of the way soon;
///   3. robots whose targets lie on fewest other robots' ways first (ties: shortest way
///      first): a robot parked on a target that others must cross is pushed off it again, and
///      each push makes its path longer; those robots go last.
/// Only the first order honours those precedences: in a city's dead-end streets they get more
/// robots home, but where every order gets every robot home anyway (the benchmark's mazes) they
/// can make the plan longer, and the second order, without them, is still there to keep.
#include <vector>

#include "fleet_planner/solvers/search/agent_conflicts.h"
#include "fleet_planner/solvers/search/search_space.h"

namespace fleet_planner {

/// Agent a's way home alone, down its distance table from its start (among the static
/// obstacles only; the first action in enum order at each step); empty if unreachable.
StatePath shortestWay(const SearchSpace& space, int a);

/// Agent a at some state of `way` covers a cell of agent b's footprint at b's target.
bool wayCoversTarget(const SearchSpace& space, int a, const StatePath& way, int b);

/// For each agent, how many other agents' `ways` (a path per agent, empty: none) cover a cell
/// of its footprint at its target at some state along them.
std::vector<int> targetsCrossed(const SearchSpace& space, const std::vector<StatePath>& ways);

/// The first `count` of the orders above (1-3), orders equal to an earlier one left out; the
/// ways of order 3 are the agents' shortestWay. With `precedence_expansions` > 0, order 1
/// honours parkingPrecedence over the same ways, each pair decided within that many expansions.
std::vector<std::vector<int>> parkingOrders(const SearchSpace& space, const std::vector<int>& longest_first,
                                            int count, long long precedence_expansions = 0);

}  // namespace fleet_planner
