#pragma once
/// How many agents one LA-LNS repair replans (la_lns.h). Small neighbourhoods repair fast but
/// settle in local minima of a few colliding pairs: after `stall_repairs` repairs without a new
/// lowest number of colliding pairs the size doubles, up to every agent of the subproblem
/// (colliding or not); a new lowest number brings it back to `base`. A stall at every agent is
/// counted: the search is stuck wherever it looks (exhausted()).
#include <algorithm>
#include <limits>

namespace fleet_planner {

class NeighborhoodGrowth {
 public:
  NeighborhoodGrowth(int base, int stall_repairs, int agents)
      : base_(std::min(base, agents)), stall_repairs_(stall_repairs), agents_(agents), size_(base_) {}

  /// Called before each repair with the number of colliding pairs then; the repair's size.
  int next(int colliding_pairs) {
    if (colliding_pairs < best_) {
      best_ = colliding_pairs;
      stalled_ = 0;
      since_best_ = 0;
      size_ = base_;
      stalls_at_every_agent_ = 0;
    } else if (++since_best_, ++stalled_ >= stall_repairs_) {
      if (size_ == agents_) ++stalls_at_every_agent_;
      size_ = std::min(2 * size_, agents_);
      stalled_ = 0;
    }
    return size_;
  }

  /// Stalls (stall_repairs repairs each) since the last new lowest number of colliding pairs
  /// with every agent in the neighbourhood.
  int exhausted() const { return stalls_at_every_agent_; }
  /// Repairs since the last new lowest number of colliding pairs (whatever their size).
  int sinceBest() const { return since_best_; }

 private:
  int base_;
  int stall_repairs_;
  int agents_;
  int size_;
  int best_ = std::numeric_limits<int>::max();
  int stalled_ = 0;     // repairs since best_ was reached or the size last grew
  int since_best_ = 0;  // repairs since best_ was reached
  int stalls_at_every_agent_ = 0;
};

}  // namespace fleet_planner
