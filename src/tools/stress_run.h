#pragma once
/// One stress instance solved with every configuration, and the checks of each run:
/// - a SUCCESS plan passes the independent validator (plan_validator.h);
/// - a non-success has an expected status (TIMEOUT or INFEASIBLE: the instances are valid, no
///   cancel flag is set, no resource limit is near) and a non-empty reason;
/// - no exception escapes the solve call (state graphs + planLayered);
/// - the solve call returns within `max_overrun_ms` of its time limit;
/// - no configuration proves INFEASIBLE an instance that another one solved;
/// - on a re-run (every few instances), the same seed gives the same plan.
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fleet_planner/runtime/resource_limits.h"
#include "stress_cases.h"

namespace fleet_planner::cli {

/// A backend and a mode: steps 0 = raw (the fleet as one subproblem), else layered with
/// decomposition steps 1..steps.
struct StressConfig {
  std::string backend;
  int steps = 0;
  /// "la_cbs/raw", "la_lacam/1234".
  std::string name() const;
  /// The `--modes` word: "raw", "1", "12", "123", "1234".
  std::string mode() const;
};

struct StressRunOptions {
  std::vector<StressConfig> configs;
  double time_limit = 0.3;  ///< seconds; each run's limit is drawn in [min_time_limit, time_limit]
  double min_time_limit = 0.3;
  int threads = 1;              ///< graphs and relation graphs, per solve
  double max_overrun_ms = 100;  ///< beyond this, a run's overrun is a violation
  ResourceLimits limits;
};

/// The time limit of `config` on instance `c` (seeded: a re-run gets the same one).
double stressTimeLimit(const StressCase& c, const StressConfig& config,
                       const StressRunOptions& options);

/// Solves `c` with every configuration (twice when `recheck`, comparing the plans) and returns
/// one JSON object: {"index", "seed", "map", "width", "height", "robots", "backward",
/// "retries", "runs": [{"config", "status", "reason", "limit_s", "wall_s", "overrun_ms",
/// "soc"?}], "violations": [{"kind", "config", "detail"}], "determinism_checked",
/// "determinism_skipped", "peak_rss_mb"}. Never throws: an exception out of a solve is a
/// violation of kind "exception". `started` (may be empty) is told each configuration just
/// before it runs.
nlohmann::json runStressCase(const StressCase& c, const StressRunOptions& options, bool recheck,
                             const std::function<void(const StressConfig&)>& started = {});

}  // namespace fleet_planner::cli
