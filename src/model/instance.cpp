#include "fleet_planner/model/instance.h"

#include <string>

#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

std::string robotLabel(const Robot& robot) {
  std::string label = "robot '" + robot.id + "'";
  if (!robot.source.empty()) label += " (" + robot.source + ")";
  return label;
}

Instance selectMixed(const Instance& pool, int k) {
  const int n = static_cast<int>(pool.robots.size());
  if (k < 1 || k > n) {
    throw InvalidInput("cannot pick " + std::to_string(k) + " mixed robots from a pool of " +
                       std::to_string(n));
  }
  std::vector<const Robot*> circles, others;
  for (const auto& r : pool.robots) {
    (r.footprint.kind == Footprint::Kind::Circle ? circles : others).push_back(&r);
  }
  int want_circles = (k + 1) / 2;
  int want_others = k / 2;
  // Where one kind runs out, the other kind fills the rest.
  if (want_circles > static_cast<int>(circles.size())) {
    want_others += want_circles - static_cast<int>(circles.size());
    want_circles = static_cast<int>(circles.size());
  }
  if (want_others > static_cast<int>(others.size())) {
    want_circles += want_others - static_cast<int>(others.size());
    want_others = static_cast<int>(others.size());
  }
  Instance out;
  out.map_file = pool.map_file;
  for (int i = 0; i < std::max(want_circles, want_others); ++i) {
    if (i < want_circles) out.robots.push_back(*circles[i]);
    if (i < want_others) out.robots.push_back(*others[i]);
  }
  return out;
}

}  // namespace fleet_planner
