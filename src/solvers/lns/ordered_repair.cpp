// Prioritized replanning of a knot with the later agents at their starts; see ordered_repair.h.
#include "fleet_planner/solvers/lns/ordered_repair.h"

#include "fleet_planner/solvers/search/safe_interval_search.h"

namespace fleet_planner {

std::optional<std::vector<StatePath>> orderedRepair(const SearchSpace& space, SoftPathTable& table,
                                                    const std::vector<int>& order,
                                                    const Deadline& deadline,
                                                    long long max_expansions,
                                                    long long& expansions) {
  // A path of one state stands there for good.
  for (int a : order) table.insert(a, StatePath{space.start(a)});
  std::vector<StatePath> paths;
  for (int a : order) {
    table.remove(a);
    SafeIntervalResult r = safeIntervalSearch(space, a, table, deadline, max_expansions);
    expansions += r.expansions;
    table.insert(
        a, r.outcome == SafeIntervalResult::Outcome::Found ? r.path : StatePath{space.start(a)});
    if (r.outcome != SafeIntervalResult::Outcome::Found) break;
    paths.push_back(std::move(r.path));
  }
  for (int a : order) table.remove(a);
  if (paths.size() != order.size()) return std::nullopt;
  return paths;
}

}  // namespace fleet_planner
