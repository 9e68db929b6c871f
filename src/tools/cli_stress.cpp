// `stress`: a seeded sweep of random small instances over every backend and mode, checking every
// run (see stress_run.h). Each instance runs in a child process of its own, so that a crash or a
// hang is caught, named with a reproducer and the sweep goes on; the summary is one JSON line.
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "cli_common.h"
#include "fleet_planner/core/instance_io.h"
#include "fleet_planner/core/map_io.h"
#include "fleet_planner/solvers/registry.h"
#include "stress_cases.h"
#include "stress_run.h"

namespace fleet_planner::cli {

namespace {

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

std::string shellWord(const std::string& s) {
  if (!s.empty() && s.find_first_not_of(
                        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./,=:") ==
                        std::string::npos) {
    return s;
  }
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

/// The command that re-runs instance `index` alone (one configuration if `config` is given).
std::string reproducer(const StressOptions& o, int index, const std::string& backend,
                       const std::string& mode, double limit) {
  std::string cmd = "fleet_planner_cli stress --seed " + std::to_string(o.seed) + " --first " +
                    std::to_string(index) + " --instances 1";
  if (!backend.empty()) {
    cmd += " --backends " + backend + " --modes " + mode + " --time-limit " + number(limit) +
           " --min-time-limit " + number(limit);
  } else {
    cmd +=
        " --time-limit " + number(o.time_limit) + " --min-time-limit " + number(o.min_time_limit);
  }
  const StressCaseOptions defaults;
  if (o.cases.min_robots != defaults.min_robots)
    cmd += " --min-agents " + std::to_string(o.cases.min_robots);
  if (o.cases.max_robots != defaults.max_robots)
    cmd += " --max-agents " + std::to_string(o.cases.max_robots);
  if (o.cases.min_side != defaults.min_side)
    cmd += " --min-side " + std::to_string(o.cases.min_side);
  if (o.cases.max_side != defaults.max_side)
    cmd += " --max-side " + std::to_string(o.cases.max_side);
  if (o.threads != 1) cmd += " --threads " + std::to_string(o.threads);
  if (!o.maps_dir.empty()) cmd += " --maps-dir " + shellWord(o.maps_dir);
  cmd += " --dump-dir " +
         shellWord(o.dump_dir.empty() ? std::string("/tmp/fleet_planner_stress") : o.dump_dir);
  return cmd;
}

/// Writes instance `index` as <dir>/stress-s<seed>-i<index>.{map,yaml,txt}; the .txt lists the
/// violations and a `solve` command per configuration. Returns the .txt path.
std::string dumpInstance(const StressOptions& o, int index, const nlohmann::json& violations) {
  namespace fs = std::filesystem;
  const StressCase c = makeStressCase(o.cases, index);
  fs::create_directories(o.dump_dir);
  const std::string stem = "stress-s" + std::to_string(o.seed) + "-i" + std::to_string(index);
  const fs::path dir(o.dump_dir);
  std::ofstream(dir / (stem + ".map")) << movingAiText(c.map);
  Instance instance = c.instance;
  instance.map_file = stem + ".map";
  saveScenario(instance, (dir / (stem + ".yaml")).string());
  std::ofstream txt(dir / (stem + ".txt"));
  txt << "stress instance " << index << " of seed " << o.seed << " (instance seed " << c.seed
      << "): " << c.map_kind << " " << c.map.width() << " x " << c.map.height() << ", "
      << c.instance.robots.size() << " robots"
      << (c.model.allow_backward
              ? ", backward moves allowed (solve has no flag for them: use the stress command)"
              : "")
      << "\n\nviolations:\n";
  for (const auto& v : violations) txt << "  " << v.dump() << "\n";
  txt << "\nre-run in the sweep:\n  " << reproducer(o, index, "", "", 0)
      << "\n\nsolve one configuration:\n";
  for (const auto& v : violations) {
    if (!v.contains("backend")) continue;
    const std::string mode = v["mode"].get<std::string>();
    txt << "  fleet_planner_cli solve --map " << (dir / (stem + ".map")).string() << " --instance "
        << (dir / (stem + ".yaml")).string() << " --backend " << v["backend"].get<std::string>()
        << " --mode " << (mode == "raw" ? "raw" : "layered --steps " + mode) << " --time-limit "
        << number(v["limit_s"].get<double>()) << " --seed " << c.seed << "\n";
  }
  return (dir / (stem + ".txt")).string();
}

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

/// One instance's work, in whatever process runs it: generation, every configuration, the
/// checks. `started` is told each configuration before it runs (a crash names the last one).
nlohmann::json workOn(const StressOptions& o, const StressRunOptions& run, int index,
                      const std::function<void(const StressConfig&)>& started) {
  StressCase c;
  try {
    c = makeStressCase(o.cases, index);
  } catch (const std::exception& e) {
    return {{"generation_error", e.what()}};
  }
  const bool recheck = o.recheck_every > 0 && index % o.recheck_every == 0;
  return runStressCase(c, run, recheck, started);
}

// The time limit configuration `name` ("la_cbs/12") had on instance `index`.
double configLimit(const StressOptions& o, const StressRunOptions& run, int index,
                   const std::string& name) {
  for (const StressConfig& config : run.configs) {
    if (config.name() == name) return stressTimeLimit(makeStressCase(o.cases, index), config, run);
  }
  return o.time_limit;
}

bool writeAll(int fd, const std::string& s) {
  std::size_t done = 0;
  while (done < s.size()) {
    const ssize_t n = ::write(fd, s.data() + done, s.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

struct Child {
  pid_t pid = -1;
  int fd = -1;
  int index = 0;
  std::string buffer;
  std::string config;  // the configuration last started
  nlohmann::json result;
  std::chrono::steady_clock::time_point started;
  bool killed = false;
};

void runSweep(const StressOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  StressRunOptions run;
  for (const auto& b : o.backends) {
    for (const auto& m : o.modes)
      run.configs.push_back({b, m == "raw" ? 0 : static_cast<int>(m.size())});
  }
  run.time_limit = o.time_limit;
  run.min_time_limit = o.min_time_limit;
  run.threads = o.threads;
  run.max_overrun_ms = o.max_overrun_ms;
  run.limits = o.limits;
  // A child that has not answered after twice its time limits plus a minute is hung.
  const double budget_s =
      2.0 * static_cast<double>(run.configs.size()) * (o.time_limit + 0.5) * 2.0 + 60.0;

  Tally tally(o);
  std::ofstream log;
  if (!o.log.empty()) {
    log.open(o.log);
    if (!log) throw InvalidInput("--log " + o.log + ": cannot write");
  }
  const int progress_every =
      o.progress_every > 0 ? o.progress_every : std::max(100, o.instances / 20);
  int done = 0;
  auto finished = [&](int index, const nlohmann::json& r) {
    if (log.is_open()) log << r.dump() << "\n";
    if (r.contains("generation_error")) {
      tally.addChildFailure(index, "generation", r["generation_error"].get<std::string>(), "", 0);
    } else {
      tally.addInstance(r);
    }
    if (++done % progress_every == 0) tally.progress(secondsSince(t0), done);
  };

  if (o.no_fork) {
    for (int i = o.first; i < o.first + o.instances; ++i) finished(i, workOn(o, run, i, nullptr));
  } else {
    ::signal(SIGPIPE, SIG_IGN);
    std::vector<Child> children;
    int next = o.first;
    const int end = o.first + o.instances;
    while (next < end || !children.empty()) {
      while (static_cast<int>(children.size()) < o.jobs && next < end) {
        int fds[2];
        if (::pipe(fds) != 0)
          throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
        std::cout.flush();
        std::cerr.flush();
        const pid_t pid = ::fork();
        if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
        if (pid == 0) {
          ::close(fds[0]);
          for (const Child& other : children) ::close(other.fd);
          const int out = fds[1];
          const nlohmann::json r = workOn(o, run, next, [out](const StressConfig& config) {
            writeAll(out, "S " + config.name() + "\n");
          });
          writeAll(out, "R " + r.dump() + "\n");
          ::_exit(0);
        }
        ::close(fds[1]);
        Child child;
        child.pid = pid;
        child.fd = fds[0];
        child.index = next++;
        child.started = std::chrono::steady_clock::now();
        children.push_back(std::move(child));
      }
      std::vector<pollfd> polls;
      for (const Child& c : children) polls.push_back({c.fd, POLLIN, 0});
      ::poll(polls.data(), polls.size(), 200);
      for (std::size_t k = 0; k < children.size();) {
        Child& c = children[k];
        bool eof = false;
        if (polls[k].revents != 0) {
          char buf[65536];
          const ssize_t n = ::read(c.fd, buf, sizeof(buf));
          if (n > 0)
            c.buffer.append(buf, static_cast<std::size_t>(n));
          else if (n == 0 || errno != EINTR)
            eof = true;
          for (std::size_t nl; (nl = c.buffer.find('\n')) != std::string::npos;
               c.buffer.erase(0, nl + 1)) {
            const std::string line = c.buffer.substr(0, nl);
            if (line.rfind("S ", 0) == 0) c.config = line.substr(2);
            if (line.rfind("R ", 0) == 0) c.result = nlohmann::json::parse(line.substr(2));
          }
        }
        if (!eof && !c.killed && secondsSince(c.started) > budget_s) {
          ::kill(c.pid, SIGKILL);
          c.killed = true;
        }
        if (!eof) {
          ++k;
          continue;
        }
        int status = 0;
        ::waitpid(c.pid, &status, 0);
        ::close(c.fd);
        const double limit = c.config.empty() ? 0.0 : configLimit(o, run, c.index, c.config);
        const std::string while_running =
            c.config.empty() ? std::string("the generator") : c.config;
        if (c.killed) {
          tally.addChildFailure(c.index, "hang",
                                "no answer after " + number(std::round(budget_s)) +
                                    " s (killed) while running " + while_running,
                                c.config, limit);
          ++done;
        } else if (WIFSIGNALED(status)) {
          tally.addChildFailure(c.index, "crash",
                                "signal " + std::to_string(WTERMSIG(status)) + " (" +
                                    strsignal(WTERMSIG(status)) + ") while running " +
                                    while_running,
                                c.config, limit);
          ++done;
        } else if (c.result.is_null()) {
          tally.addChildFailure(c.index, "crash",
                                "exit status " + std::to_string(WEXITSTATUS(status)) +
                                    " without a result while running " + while_running,
                                c.config, limit);
          ++done;
        } else {
          finished(c.index, c.result);
        }
        children.erase(children.begin() + static_cast<std::ptrdiff_t>(k));
        polls.erase(polls.begin() + static_cast<std::ptrdiff_t>(k));
      }
    }
  }
  if (done % progress_every != 0) tally.progress(secondsSince(t0), done);
  printJsonLine(tally.summary(secondsSince(t0)));
  if (tally.violations() > 0) setExitCode(1);
}

}  // namespace

void addStressCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("stress",
                                 "seeded sweep of random small instances over every backend and "
                                 "mode; checks every run (exit 1 on a violation)");
  auto o = std::make_shared<StressOptions>();
  cmd->add_option("--instances", o->instances, "number of instances")->check(CLI::PositiveNumber);
  cmd->add_option("--first", o->first,
                  "index of the first instance (re-run one with --first I --instances 1)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", o->seed, "base seed: instance I of seed S is always the same");
  cmd->add_option("--time-limit", o->time_limit,
                  "seconds per solve call, state graphs included (the largest, "
                  "with --min-time-limit)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--min-time-limit", o->min_time_limit,
                  "draw each run's limit in [this, --time-limit], seeded (default: --time-limit)");
  cmd->add_option("--jobs", o->jobs, "instances run at once, one child process each")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--threads", o->threads, "threads per solve (graphs, relation graphs)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--backends", o->backends, "backends to run")->delimiter(',');
  cmd->add_option("--modes", o->modes, "raw and/or decomposition steps 1, 12, 123, 1234")
      ->delimiter(',')
      ->check(CLI::IsMember({"raw", "1", "12", "123", "1234"}));
  cmd->add_option("--recheck-every", o->recheck_every,
                  "solve every K-th instance twice and compare the plans (0: never)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--max-overrun-ms", o->max_overrun_ms,
                  "a solve call longer than its limit plus this is a violation");
  cmd->add_option("--maps-dir", o->maps_dir, "MovingAI maps (*.map) to crop small maps from");
  cmd->add_option("--dump-dir", o->dump_dir,
                  "write each failing instance here (.map, .yaml, .txt with commands)");
  cmd->add_option("--log", o->log, "write every instance's runs here, one JSON line per instance");
  cmd->add_flag("--no-fork", o->no_fork,
                "run in this process (for a debugger; a crash ends the sweep)");
  cmd->add_option("--progress-every", o->progress_every,
                  "progress line every N instances (default: 5 %)");
  cmd->add_option("--max-printed", o->max_printed,
                  "violations printed in full (the rest are counted)");
  cmd->add_option("--min-agents", o->cases.min_robots, "fewest robots per instance")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--max-agents", o->cases.max_robots, "most robots per instance")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--min-side", o->cases.min_side, "smallest map side (cells)")
      ->check(CLI::Range(4, 1000));
  cmd->add_option("--max-side", o->cases.max_side, "largest map side (cells)")
      ->check(CLI::Range(4, 1000));
  addLimitOptions(cmd, o->limits);
  cmd->callback([o] {
    if (o->min_time_limit < 0) o->min_time_limit = o->time_limit;
    if (o->min_time_limit > o->time_limit)
      throw InvalidInput("--min-time-limit must not exceed --time-limit");
    if (o->cases.min_robots > o->cases.max_robots)
      throw InvalidInput("--min-agents must not exceed --max-agents");
    if (o->cases.min_side > o->cases.max_side)
      throw InvalidInput("--min-side must not exceed --max-side");
    if (o->backends.empty() || o->modes.empty())
      throw InvalidInput("--backends and --modes must not be empty");
    for (const auto& b : o->backends)
      makeSolver(b);  // an unknown name: InvalidInput listing the known ones
    if (!o->maps_dir.empty()) {
      std::vector<std::string> paths;
      for (const auto& entry : std::filesystem::directory_iterator(o->maps_dir)) {
        if (entry.path().extension() == ".map") paths.push_back(entry.path().string());
      }
      std::sort(paths.begin(),
                paths.end());  // the order of the directory must not change the instances
      if (paths.empty()) throw InvalidInput("--maps-dir " + o->maps_dir + ": no .map files");
      for (const auto& p : paths) o->cases.crop_maps.push_back(loadMovingAiMap(p));
    }
    runSweep(*o);
  });
}

}  // namespace fleet_planner::cli
