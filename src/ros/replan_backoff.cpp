#include "fleet_planner/ros/replan_backoff.h"

#include <algorithm>
#include <stdexcept>

namespace fleet_planner {

ReplanBackoff::ReplanBackoff(double base_s, double max_s) : base_s_(base_s), max_s_(max_s) {
  if (!(base_s > 0.0) || !(max_s >= base_s)) throw std::invalid_argument("ReplanBackoff: need 0 < base_s <= max_s");
}

bool ReplanBackoff::due(const std::string& key, double now_s, const std::string& cause) const {
  const auto it = tries_.find(key);
  if (it == tries_.end()) return true;
  const Try& last = it->second;
  // A changed cause is tried again as if the last try had been merged.
  const double wait_s = last.cause == cause ? last.wait_s : base_s_;
  return now_s - last.at_s >= wait_s;
}

void ReplanBackoff::record(const std::string& key, double now_s, const std::string& cause, bool merged) {
  const auto it = tries_.find(key);
  const double before_s = it != tries_.end() && it->second.cause == cause ? it->second.wait_s : base_s_;
  tries_[key] = Try{now_s, merged ? base_s_ : std::min(before_s * 2.0, max_s_), cause};
}

double ReplanBackoff::wait(const std::string& key) const {
  const auto it = tries_.find(key);
  return it == tries_.end() ? base_s_ : it->second.wait_s;
}

}  // namespace fleet_planner
