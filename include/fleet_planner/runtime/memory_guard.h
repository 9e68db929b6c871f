#pragma once
/// A memory limit that running searches honour like a deadline: attached to a Deadline
/// (Deadline::withMemoryGuard), it makes Deadline::expired() true once the process's resident
/// memory has passed `max_memory_mb`, so every loop that checks its deadline also stops before
/// the machine runs out of memory. The searches then report RESOURCE_LIMIT with reason().
///
/// Resident memory (VmRSS) is sampled at most once per interval (10 ms by default), so a check
/// costs a clock read between samples. Before it trips, the guard hands memory that the
/// allocator holds but no longer uses back to the system (glibc malloc_trim) and samples again,
/// so that freed memory of an earlier search does not count. Once tripped it stays tripped.
/// Thread-safe; one guard serves one planning call (and every thread of it).
#include <atomic>
#include <chrono>
#include <string>

#include "fleet_planner/runtime/resource_limits.h"

namespace fleet_planner {

class MemoryGuard {
 public:
  using Clock = std::chrono::steady_clock;

  explicit MemoryGuard(double max_memory_mb,
                       Clock::duration interval = std::chrono::milliseconds(10))
      : limit_mb_(max_memory_mb), interval_(interval.count()) {}
  MemoryGuard(const MemoryGuard&) = delete;
  MemoryGuard& operator=(const MemoryGuard&) = delete;

  double limitMb() const { return limit_mb_; }

  /// True once the resident memory has been seen above the limit (sampled, see above).
  bool exceeded(Clock::time_point now = Clock::now()) const {
    if (tripped_.load(std::memory_order_relaxed)) return true;
    if (now.time_since_epoch().count() < next_sample_.load(std::memory_order_relaxed)) return false;
    return sample(now);
  }

  /// Throws ResourceLimitError (max_memory_mb) if the resident memory now plus `extra_mb` would
  /// pass the limit: for a search about to allocate `extra_mb` for `what`.
  void reserve(double extra_mb, const std::string& what) const;

  /// Largest resident memory sampled so far, in MB.
  double peakSampledMb() const { return peak_mb_.load(std::memory_order_relaxed); }

  /// "the process's resident memory reached 4100.2 MB, over max_memory_mb=4096".
  std::string reason() const;

 private:
  bool sample(Clock::time_point now) const;

  const double limit_mb_;
  const Clock::rep interval_;
  mutable std::atomic<Clock::rep> next_sample_{0};
  mutable std::atomic<bool> tripped_{false};
  mutable std::atomic<double> peak_mb_{0.0};
};

}  // namespace fleet_planner
