#include "fleet_planner/ros/planner_config.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "fleet_planner/model/footprint.h"
#include "fleet_planner/ros/backend_loader.h"

namespace fleet_planner {

namespace {

template <typename T>
std::string show(const T& v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

class Checker {
 public:
  void positive(const char* name, double v) {
    if (!(v > 0) || !std::isfinite(v)) add(name, "must be > 0 and finite", v);
  }
  void nonNegative(const char* name, double v) {
    if (!(v >= 0) || !std::isfinite(v)) add(name, "must be >= 0 and finite", v);
  }
  /// v <= limit (the parameter `limit_name`); only checked when both are usable numbers.
  void atMost(const char* name, double v, const char* limit_name, double limit) {
    if (v > 0 && std::isfinite(v) && limit > 0 && std::isfinite(limit) && v > limit) {
      add(name, "must be <= " + std::string(limit_name) + " (" + show(limit) + ")", v);
    }
  }
  void between(const char* name, double v, double lo, double hi) {
    if (!(v >= lo && v <= hi)) add(name, "must be in [" + show(lo) + ", " + show(hi) + "]", v);
  }
  void range(const char* name, int v, int lo, int hi) {
    if (v < lo || v > hi) add(name, "must be in " + show(lo) + ".." + show(hi), v);
  }
  void oneOf(const char* name, const std::string& v, const std::vector<std::string>& allowed) {
    for (const auto& a : allowed) {
      if (v == a) return;
    }
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : " or ") + ("'" + a + "'");
    add(name, "must be " + list, "'" + v + "'");
  }
  void nonEmpty(const char* name, const std::string& v) {
    if (v.empty()) errors.push_back(std::string(name) + " must not be empty");
  }
  std::vector<std::string> errors;

 private:
  template <typename T>
  void add(const char* name, const std::string& rule, const T& got) {
    errors.push_back(std::string(name) + " " + rule + " (got " + show(got) + ")");
  }
};

}  // namespace

PlanningOptions planningOptions(const PlannerConfig& c) {
  PlanningOptions o;
  o.backend = c.backend;
  o.fallback = c.fallback;
  o.backend_parameters = c.backend_parameters;
  o.decompose = c.decomposition;
  o.last_step = c.decomposition_steps;
  o.threads = c.threads;
  o.refine = c.refine;
  o.compress = c.compress;
  o.cell_steps = c.cell_steps;
  o.time_limit = c.time_limit;
  o.limits = c.resourceLimits();
  return o;
}

std::vector<std::string> checkPlannerBackends(const PlannerConfig& c) {
  std::vector<std::string> problems;
  PlanningOptions o = planningOptions(c);
  std::string why_not;
  o.backend = resolveBackendName(c.backend, &why_not);
  if (o.backend.empty()) problems.push_back("backend: " + why_not);
  if (!c.fallback.empty()) {
    o.fallback = resolveBackendName(c.fallback, &why_not);
    if (o.fallback.empty()) problems.push_back("fallback: " + why_not);
  }
  if (!problems.empty()) return problems;
  return checkPlanningOptions(o);  // "fallback: ...", "backend_parameters: ..."
}

std::vector<std::string> checkPlannerConfig(const PlannerConfig& c) {
  Checker check;
  check.nonEmpty("backend", c.backend);
  check.positive("time_limit", c.time_limit);
  check.positive("max_time_limit", c.max_time_limit);
  check.atMost("time_limit", c.time_limit, "max_time_limit", c.max_time_limit);
  check.range("decomposition_steps", c.decomposition_steps, 1, 4);
  check.range("threads", c.threads, 0, 64);
  check.oneOf("busy_policy", c.busy_policy, {"reject", "queue"});
  check.range("max_map_cells", c.max_map_cells, 1, std::numeric_limits<int>::max());
  check.range("max_robots", c.max_robots, 1, std::numeric_limits<int>::max());
  check.positive("max_memory_mb", c.max_memory_mb);
  check.range("occupied_threshold", c.occupied_threshold, 1, 100);
  check.oneOf("unknown_policy", c.unknown_policy, {"obstacle", "free"});
  check.nonNegative("lattice_resolution", c.lattice_resolution);
  check.nonNegative("position_tolerance", c.position_tolerance);
  check.nonNegative("heading_tolerance", c.heading_tolerance);
  check.between("sweep_tolerance", c.sweep_tolerance, 0.0, Footprint::kMaxSweepTolerance);
  check.positive("seconds_per_step", c.seconds_per_step);
  check.nonEmpty("map_frame", c.map_frame);
  check.nonEmpty("base_frame", c.base_frame);
  check.nonNegative("tf_timeout", c.tf_timeout);
  check.nonEmpty("planned_frame", c.planned_frame);
  check.positive("playback_rate", c.playback_rate);
  check.positive("execution_rate", c.execution_rate);
  check.positive("progress_tolerance", c.progress_tolerance);
  check.positive("progress_heading_tolerance", c.progress_heading_tolerance);
  check.positive("blocked_timeout", c.blocked_timeout);
  check.nonNegative("late_warning", c.late_warning);
  check.positive("off_path_tolerance", c.off_path_tolerance);
  check.positive("replan_time_limit", c.replan_time_limit);
  return check.errors;
}

}  // namespace fleet_planner
