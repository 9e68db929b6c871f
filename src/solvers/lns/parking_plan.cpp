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
  // An order is in the running while it has spent at most `order_slack` times the expansions of
  // an order that got every agent home.
  auto reach = [&](long long e) { return static_cast<long long>(options.order_slack * static_cast<double>(e)); };
  // Order i, having spent `used`, is out of the running (or, without slack, ties with an
  // earlier order).
  auto beaten = [&](int i, long long used) {
    for (int j = 0; j < k; ++j) {
      const long long e = j == i ? kNotHome : home[j].load();
      if (e != kNotHome && (used > reach(e) || (used == e && j < i && reach(e) == e))) return true;
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
  int fastest = -1;
  for (int i = 0; i < k; ++i) {
    if (home[i] != kNotHome && (fastest < 0 || home[i] < home[fastest])) fastest = i;
  }
  if (fastest < 0) {  // nobody gave way: every order ran its course
    // The plan that got most robots home (ties: the earlier order): its end game is smallest.
    int most = -1;
    for (int i = 0; i < k; ++i) {
      expansions += spent[i];
      if (plans[i] && (most < 0 || plans[i]->robots_home > plans[most]->robots_home)) most = i;
    }
    if (most < 0) return std::nullopt;  // every order's plan failed its final check
    plans[most]->order = most;
    return plans[most];
  }
  // Of the orders home within the slack of the fastest (whatever the threads: an order within
  // it never gives way), the plan of least sum of costs; ties: fewer expansions, then the
  // earlier order.
  const long long limit = reach(home[fastest].load());
  auto soc = [&](int i) {
    long long c = 0;
    for (const StatePath& p : plans[i]->paths) c += static_cast<long long>(p.size()) - 1;
    return c;
  };
  int best = fastest;
  for (int i = 0; i < k; ++i) {
    if (i == fastest || home[i] == kNotHome || home[i] > limit) continue;
    const long long a = soc(i), b = soc(best);
    if (a < b || (a == b && (home[i] < home[best] || (home[i] == home[best] && i < best)))) best = i;
  }
  for (int i = 0; i < k; ++i) expansions += std::min(spent[i], limit);
  plans[best]->order = best;
  return plans[best];
}

}  // namespace fleet_planner
