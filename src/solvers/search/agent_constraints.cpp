#include "fleet_planner/solvers/search/agent_constraints.h"

#include <algorithm>

namespace fleet_planner {

namespace {
bool covers(const CellSet& set, const GridPose& p, const Cell& c) { return set.contains(c.x - p.x, c.y - p.y); }
}  // namespace

void AgentConstraints::add(const Entry& e) {
  by_time_[e.t].push_back(e);
  all_.push_back(e);
  max_time_ = std::max(max_time_, e.during ? e.t + 1 : e.t);
}

void AgentConstraints::forbidAreaFrom(const CellSet& area, Cell origin, int t) {
  areas_.push_back({&area, origin, t});
  max_time_ = std::max(max_time_, t);
  areas_from_ = std::max(areas_from_, t);
}

void AgentConstraints::requireCostAbove(int t) {
  min_cost_ = std::max(min_cost_, t + 1);
  max_time_ = std::max(max_time_, t + 1);
}

void AgentConstraints::requireCostAtMost(int t) {
  max_cost_ = std::min(max_cost_, t);
  max_time_ = std::max(max_time_, t);
}

bool AgentConstraints::areaHit(const CellSet& mine, const GridPose& p, int t) const {
  for (const Area& a : areas_) {
    if (t >= a.from && CellSet::overlap(mine, {p.x, p.y}, *a.cells, a.origin)) return true;
  }
  return false;
}

bool AgentConstraints::poseForbidden(const FootprintCells& cells, const GridPose& p, int t) const {
  if (!areas_.empty() && areaHit(cells.body(p.heading), p, t)) return true;
  if (all_.empty()) return false;
  const auto it = by_time_.find(t);
  if (it == by_time_.end()) return false;
  for (const Entry& e : it->second) {
    if (!e.during && covers(cells.body(p.heading), p, e.c)) return true;
  }
  return false;
}

bool AgentConstraints::stepForbidden(const FootprintCells& cells, const GridPose& p, Action action, int t) const {
  if (!areas_.empty() && areaHit(cells.swept(p.heading, action), p, t)) return true;
  if (all_.empty()) return false;
  const auto it = by_time_.find(t);
  if (it == by_time_.end()) return false;
  for (const Entry& e : it->second) {
    if (e.during && covers(cells.swept(p.heading, action), p, e.c)) return true;
  }
  return false;
}

int AgentConstraints::lastBlockedAt(const FootprintCells& cells, const GridPose& p) const {
  for (const Area& a : areas_) {
    if (CellSet::overlap(cells.body(p.heading), {p.x, p.y}, *a.cells, a.origin)) return kForever;
  }
  int last = -1;
  for (const Entry& e : all_) {
    // Waiting at p sweeps exactly its footprint.
    if (e.t > last && covers(cells.body(p.heading), p, e.c)) last = e.t;
  }
  return last;
}

}  // namespace fleet_planner
