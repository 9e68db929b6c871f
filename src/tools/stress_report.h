#pragma once
// The stress command's options and its report: the reproducer of an instance, the dump of a
// failing instance, and the sweep's totals (Tally). Private to the CLI (cli_stress.cpp).
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fleet_planner/runtime/resource_limits.h"
#include "stress_cases.h"

namespace fleet_planner::cli {

/// The stress command's options.
struct StressOptions {
  int instances = 1000;
  int first = 0;
  std::uint64_t seed = 0;
  double time_limit = 0.3;
  double min_time_limit = -1;  // -1: the same as time_limit
  int jobs = 1;
  int threads = 1;
  std::vector<std::string> backends{"la_cbs", "la_lacam", "la_lns"};
  std::vector<std::string> modes{"raw", "1", "12", "123", "1234"};
  int recheck_every = 10;
  double max_overrun_ms = 100;
  std::string maps_dir;
  std::string dump_dir;
  std::string log;  // one JSON line per instance
  bool no_fork = false;
  int progress_every = 0;
  int max_printed = 20;
  StressCaseOptions cases;
  ResourceLimits limits;
};

/// `v` as the shortest text that reads back the same ("0.25", "100").
std::string number(double v);

/// The command that re-runs instance `index` alone (one configuration if `backend` is given).
std::string reproducer(const StressOptions& o, int index, const std::string& backend, const std::string& mode,
                       double limit);

/// Writes instance `index` as <dir>/stress-s<seed>-i<index>.{map,yaml,txt}; the .txt lists the
/// violations and a `solve` command per configuration. Returns the .txt path.
std::string dumpInstance(const StressOptions& o, int index, const nlohmann::json& violations);

/// The sweep's totals and the violations found.
class Tally {
 public:
  explicit Tally(const StressOptions& o) : o_(o) {}

  void addInstance(const nlohmann::json& r) {
    ++instances_;
    retries_ += r.value("retries", 0);
    determinism_checked_ += r.value("determinism_checked", 0);
    determinism_skipped_ += r.value("determinism_skipped", 0);
    max_rss_mb_ = std::max(max_rss_mb_, r.value("peak_rss_mb", 0.0));
    maps_[r.value("map", std::string("?")).substr(0, 4) == "crop"
              ? std::string("crop")
              : r.value("map", std::string("?"))]++;
    for (const auto& run : r["runs"]) {
      ++runs_;
      const std::string status = run["status"].get<std::string>();
      const std::string config = run["config"].get<std::string>();
      auto& per = by_config_[config];
      if (per.is_null()) per = nlohmann::json::object();
      per["runs"] = per.value("runs", 0) + 1;
      if (status == "SUCCESS") {
        ++success_;
        per["success"] = per.value("success", 0) + 1;
      } else {
        ++non_success_[status];
        per[status] = per.value(status, 0) + 1;
      }
      const double overrun = run["overrun_ms"].get<double>();
      const double first = run.value("first_overrun_ms", overrun);
      max_first_overrun_ms_ = std::max(max_first_overrun_ms_, first);
      max_cpu_overrun_ms_ = std::max(
          max_cpu_overrun_ms_, (run["cpu_s"].get<double>() - run["limit_s"].get<double>()) * 1000);
      if (run.contains("attempts")) ++overrun_retries_;
      if (overrun > max_overrun_ms_) {
        max_overrun_ms_ = overrun;
        worst_overrun_ = {{"instance", r["index"]},  {"config", config},
                          {"status", status},        {"limit_s", run["limit_s"]},
                          {"wall_s", run["wall_s"]}, {"cpu_s", run["cpu_s"]}};
      }
    }
    for (const auto& v : r["violations"]) {
      addViolation(r["index"].get<int>(), v);
    }
    if (!r["violations"].empty()) dump(r["index"].get<int>(), r["violations"]);
  }

  void addChildFailure(int index, const std::string& kind, const std::string& detail,
                       const std::string& config, double limit) {
    nlohmann::json v{{"kind", kind}, {"detail", detail}};
    if (!config.empty()) {
      v["config"] = config;
      v["backend"] = config.substr(0, config.find('/'));
      v["mode"] = config.substr(config.find('/') + 1);
      v["limit_s"] = limit;
    }
    ++instances_failed_;
    addViolation(index, v);
    dump(index, nlohmann::json::array({v}));
  }

  void progress(double elapsed, int done) const {
    std::cerr << "stress: " << done << "/" << o_.instances << " instances, " << runs_ << " runs, "
              << success_ << " successes, " << violations_ << " violations, max overrun "
              << number(std::round(max_overrun_ms_)) << " ms, " << number(std::round(elapsed))
              << " s" << std::endl;
  }

  int violations() const { return violations_; }

  nlohmann::json summary(double elapsed) const {
    nlohmann::json by_status = nlohmann::json::object();
    for (const auto& [status, n] : non_success_) by_status[status] = n;
    nlohmann::json by_kind = nlohmann::json::object();
    for (const auto& [kind, n] : kinds_) by_kind[kind] = n;
    nlohmann::json configs = nlohmann::json::object();
    for (const auto& [name, per] : by_config_) configs[name] = per;
    nlohmann::json maps = nlohmann::json::object();
    for (const auto& [kind, n] : maps_) maps[kind] = n;
    auto count = [&](const char* kind) {
      const auto it = kinds_.find(kind);
      return it == kinds_.end() ? 0 : it->second;
    };
    return {{"instances", instances_},
            {"runs", runs_},
            {"success", success_},
            {"non_success_by_status", by_status},
            {"invalid_plans", count("invalid_plan")},
            {"crashes", count("crash")},
            {"hangs", count("hang")},
            {"exceptions", count("exception")},
            {"empty_reasons", count("empty_reason")},
            {"unexpected_statuses", count("unexpected_status")},
            {"infeasible_contradictions", count("infeasible_contradiction")},
            {"overruns", count("overrun")},
            {"max_overrun_ms", max_overrun_ms_},
            {"max_overrun_first_try_ms", max_first_overrun_ms_},
            {"overrun_retried_runs", overrun_retries_},
            {"max_cpu_overrun_ms", max_cpu_overrun_ms_},
            {"worst_overrun", worst_overrun_},
            {"nondeterministic", count("nondeterministic")},
            {"determinism_checked", determinism_checked_},
            {"determinism_skipped", determinism_skipped_},
            {"violations", violations_},
            {"violations_by_kind", by_kind},
            {"instances_failed", instances_failed_},
            {"generator_retries", retries_},
            {"maps", maps},
            {"by_config", configs},
            {"seed", o_.seed},
            {"first", o_.first},
            {"time_limit", o_.time_limit},
            {"min_time_limit", o_.min_time_limit},
            {"max_overrun_bound_ms", o_.max_overrun_ms},
            {"jobs", o_.jobs},
            {"max_child_rss_mb", max_rss_mb_},
            {"elapsed_s", elapsed},
            {"ok", violations_ == 0}};
  }

 private:
  void addViolation(int index, const nlohmann::json& v) {
    ++violations_;
    ++kinds_[v["kind"].get<std::string>()];
    if (violations_ > o_.max_printed) {
      if (violations_ == o_.max_printed + 1)
        std::cerr << "stress: (further violations are counted, not printed)\n";
      return;
    }
    const bool one = v.contains("backend");
    std::cerr << "stress: VIOLATION " << v["kind"].get<std::string>() << " in instance " << index
              << (one ? ", " + v["config"].get<std::string>() + ", time limit " +
                            number(v["limit_s"].get<double>()) + " s"
                      : std::string())
              << ": " << v["detail"].get<std::string>() << "\n  reproduce: "
              << reproducer(o_, index, one ? v["backend"].get<std::string>() : "",
                            one ? v["mode"].get<std::string>() : "",
                            one ? v["limit_s"].get<double>() : 0)
              << std::endl;
  }

  void dump(int index, const nlohmann::json& violations) {
    if (o_.dump_dir.empty()) return;
    try {
      std::cerr << "stress: instance " << index
                << " dumped: " << dumpInstance(o_, index, violations) << std::endl;
    } catch (const std::exception& e) {
      std::cerr << "stress: could not dump instance " << index << ": " << e.what() << std::endl;
    }
  }

  const StressOptions& o_;
  int instances_ = 0, instances_failed_ = 0, runs_ = 0, success_ = 0, violations_ = 0, retries_ = 0;
  int determinism_checked_ = 0, determinism_skipped_ = 0;
  double max_overrun_ms_ = -1e9, max_first_overrun_ms_ = -1e9, max_cpu_overrun_ms_ = -1e9,
         max_rss_mb_ = 0;
  int overrun_retries_ = 0;
  nlohmann::json worst_overrun_;
  std::map<std::string, int> non_success_, kinds_, maps_;
  std::map<std::string, nlohmann::json> by_config_;
};

}  // namespace fleet_planner::cli
