#pragma once
/// The race of LA-LNS's two searches (la_lns.h, LaLnsOptions::portfolio_robots): two copies of
/// one first plan repaired on two threads, each search with its own seed. Each records the
/// repairs after which it reached its outcome (a plan, a proof, giving up), and the outcome after
/// fewer repairs wins, ties to search 0. A search stops as soon as the other's outcome beats any
/// it could still reach, so the winner does not depend on which thread runs faster.
#include <array>
#include <atomic>

namespace fleet_planner {

struct LnsRace {
  static constexpr long long kNone = -1;
  std::array<std::atomic<long long>, 2> outcome_at{{kNone, kNone}};
  std::array<std::atomic<long long>, 2> repairs{{0, 0}};  // made so far, by search
  std::atomic<bool> call_off{false};                      // search 1's cancel flag
  /// Search `me` cannot win with an outcome after `at` repairs.
  bool beaten(int me, long long at) const {
    const long long o = outcome_at[1 - me].load();
    return o != kNone && (o < at || (o == at && me == 1));
  }
};

}  // namespace fleet_planner
