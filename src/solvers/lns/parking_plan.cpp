// One robot at a time, the robots in its way pushed into pockets; see parking_plan.h.
#include "fleet_planner/solvers/lns/parking_plan.h"

#include <atomic>
#include <climits>
#include <exception>
#include <thread>

#include "parking.h"

namespace fleet_planner {

std::optional<ParkingPlan> parkingPlan(const SearchSpace& space, const std::vector<int>& order,
                                       const Deadline& deadline, const ParkingPlanOptions& options,
                                       long long& expansions) {
  Parking parking(space, deadline, options);
  std::optional<ParkingPlan> plan = parking.run(order);
  expansions += parking.spent();
  return plan;
}

std::optional<ParkingPlan> fastestParkingPlan(const SearchSpace& space,
                                              const std::vector<std::vector<int>>& orders,
                                              const Deadline& deadline,
                                              const ParkingPlanOptions& options, int threads,
                                              long long& expansions) {
  const int k = static_cast<int>(orders.size());
  if (k == 0) return std::nullopt;
  constexpr long long kNotHome = LLONG_MAX;
  // Expansions at which order i got every agent home (kNotHome: not, or not yet).
  std::vector<std::atomic<long long>> home(k);
  for (auto& h : home) h.store(kNotHome);
  std::vector<std::optional<ParkingPlan>> plans(k);
  std::vector<long long> spent(k, 0);
  std::vector<std::exception_ptr> failures(k);
  // Order i, having spent `used`, ends with more than order j did (or as many, j first).
  auto beaten = [&](int i, long long used) {
    for (int j = 0; j < k; ++j) {
      const long long e = j == i ? kNotHome : home[j].load();
      if (e != kNotHome && (used > e || (used == e && j < i))) return true;
    }
    return false;
  };
  std::vector<std::unique_ptr<Parking>> parkings(k);
  for (int i = 0; i < k; ++i) {
    parkings[i] = std::make_unique<Parking>(space, deadline, options,
                                            [&, i](long long used) { return beaten(i, used); });
    parkings[i]->start(orders[i]);
  }
  auto end = [&](int i) {
    plans[i] = parkings[i]->finish();
    spent[i] = parkings[i]->spent();
    if (plans[i] && !parkings[i]->gaveWay() && plans[i]->robots_home == space.numAgents())
      home[i] = spent[i];
  };
  if (threads >= 2 && k >= 2) {
    // Orders 0, lanes, 2 x lanes, ... on this thread, the others on helpers.
    const int lanes = std::min(threads, k);
    auto lane = [&](int first) {
      for (int i = first; i < k; i += lanes) {
        try {
          while (parkings[i]->turn()) {
          }
          end(i);
        } catch (...) {
          failures[i] = std::current_exception();
        }
      }
    };
    std::vector<std::thread> helpers;
    for (int l = 1; l < lanes; ++l) helpers.emplace_back(lane, l);
    lane(0);
    for (std::thread& t : helpers) t.join();
    for (const std::exception_ptr& e : failures) {
      if (e) std::rethrow_exception(e);
    }
  } else {
    // One thread: the order that has spent least takes the next turn (ties: the earlier), so
    // that the orders advance together and the first to get everybody home ends the others.
    std::vector<char> running(k, 1);
    while (true) {
      int next = -1;
      for (int i = 0; i < k; ++i) {
        if (running[i] && (next < 0 || parkings[i]->spent() < parkings[next]->spent())) next = i;
      }
      if (next < 0) break;
      if (!parkings[next]->turn()) {
        running[next] = 0;
        end(next);
      }
    }
  }
  int best = -1;
  for (int i = 0; i < k; ++i) {
    if (home[i] != kNotHome && (best < 0 || home[i] < home[best])) best = i;
  }
  if (best < 0) {  // nobody gave way: every order ran its course
    for (int i = 0; i < k; ++i) expansions += spent[i];
    return plans[0];
  }
  for (int i = 0; i < k; ++i) expansions += std::min(spent[i], home[best].load());
  plans[best]->order = best;
  return plans[best];
}

}  // namespace fleet_planner
