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
#include "fleet_planner/io/instance_io.h"
#include "fleet_planner/io/map_io.h"
#include "fleet_planner/solvers/registry.h"
#include "stress_cases.h"
#include "stress_report.h"
#include "stress_run.h"

namespace fleet_planner::cli {

namespace {

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

// Forks a child that works on instance `index` and reports on a pipe: "S <config>" as each
// configuration starts, "R <json>" with the result.
Child spawnChild(const StressOptions& o, const StressRunOptions& run, int index, const std::vector<Child>& children) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    ::close(fds[0]);
    for (const Child& other : children) ::close(other.fd);
    const int out = fds[1];
    const nlohmann::json r =
        workOn(o, run, index, [out](const StressConfig& config) { writeAll(out, "S " + config.name() + "\n"); });
    writeAll(out, "R " + r.dump() + "\n");
    ::_exit(0);
  }
  ::close(fds[1]);
  Child child;
  child.pid = pid;
  child.fd = fds[0];
  child.index = index;
  child.started = std::chrono::steady_clock::now();
  return child;
}

// Reads what the child wrote; true at the end of its pipe.
bool readFromChild(Child& c) {
  bool eof = false;
  char buf[65536];
  const ssize_t n = ::read(c.fd, buf, sizeof(buf));
  if (n > 0)
    c.buffer.append(buf, static_cast<std::size_t>(n));
  else if (n == 0 || errno != EINTR)
    eof = true;
  for (std::size_t nl; (nl = c.buffer.find('\n')) != std::string::npos; c.buffer.erase(0, nl + 1)) {
    const std::string line = c.buffer.substr(0, nl);
    if (line.rfind("S ", 0) == 0) c.config = line.substr(2);
    if (line.rfind("R ", 0) == 0) c.result = nlohmann::json::parse(line.substr(2));
  }
  return eof;
}

// A child that has ended (exit `status`): true if it left a result; otherwise its hang or crash
// is tallied.
bool childEnded(const StressOptions& o, const StressRunOptions& run, const Child& c, int status, double budget_s,
                Tally& tally) {
  const double limit = c.config.empty() ? 0.0 : configLimit(o, run, c.index, c.config);
  const std::string while_running =
      c.config.empty() ? std::string("the generator") : c.config;
  if (c.killed) {
    tally.addChildFailure(c.index, "hang",
                          "no answer after " + number(std::round(budget_s)) +
                              " s (killed) while running " + while_running,
                          c.config, limit);
  } else if (WIFSIGNALED(status)) {
    tally.addChildFailure(c.index, "crash",
                          "signal " + std::to_string(WTERMSIG(status)) + " (" +
                              strsignal(WTERMSIG(status)) + ") while running " +
                              while_running,
                          c.config, limit);
  } else if (c.result.is_null()) {
    tally.addChildFailure(c.index, "crash",
                          "exit status " + std::to_string(WEXITSTATUS(status)) +
                              " without a result while running " + while_running,
                          c.config, limit);
  } else {
    return true;
  }
  return false;
}

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
        children.push_back(spawnChild(o, run, next++, children));
      }
      std::vector<pollfd> polls;
      for (const Child& c : children) polls.push_back({c.fd, POLLIN, 0});
      ::poll(polls.data(), polls.size(), 200);
      for (std::size_t k = 0; k < children.size();) {
        Child& c = children[k];
        const bool eof = polls[k].revents != 0 && readFromChild(c);
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
        if (childEnded(o, run, c, status, budget_s, tally)) {
          finished(c.index, c.result);
        } else {
          ++done;
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
