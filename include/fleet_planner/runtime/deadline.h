#pragma once
/// When a solve must stop: a point in time, an optional cancel flag and an optional memory
/// guard. Every solver checks it in its loops and returns promptly (TIMEOUT, CANCELLED or
/// RESOURCE_LIMIT) once it has passed.
#include <atomic>
#include <chrono>
#include <limits>
#include <stdexcept>

#include "fleet_planner/runtime/memory_guard.h"

namespace fleet_planner {

class Deadline {
 public:
  using Clock = std::chrono::steady_clock;

  /// No time limit, no cancel flag.
  Deadline() : end_(Clock::time_point::max()) {}
  /// Stops at `end`, or when *cancel becomes true (the flag must outlive the solve).
  explicit Deadline(Clock::time_point end, const std::atomic<bool>* cancel = nullptr)
      : end_(end), cancel_(cancel) {}
  /// `seconds` from now (non-positive: already expired; infinite: never).
  static Deadline in(double seconds, const std::atomic<bool>* cancel = nullptr) {
    if (seconds >= 1e9) return Deadline(Clock::time_point::max(), cancel);
    const auto now = Clock::now();
    if (!(seconds > 0)) return Deadline(now, cancel);
    return Deadline(now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds)),
                    cancel);
  }

  bool cancelled() const { return cancel_ != nullptr && cancel_->load(std::memory_order_relaxed); }
  bool timedOut() const { return end_ != Clock::time_point::max() && Clock::now() >= end_; }
  /// The memory guard has tripped (never without a guard).
  bool outOfMemory() const { return memory_ != nullptr && memory_->exceeded(); }
  /// Cancelled, out of time or out of memory.
  bool expired() const {
    if (cancelled()) return true;
    if (end_ == Clock::time_point::max() && memory_ == nullptr) return false;
    const auto now = Clock::now();
    return now >= end_ || (memory_ != nullptr && memory_->exceeded(now));
  }
  /// Seconds left (infinity without a limit, 0 once passed).
  double remaining() const {
    if (end_ == Clock::time_point::max()) return std::numeric_limits<double>::infinity();
    const double s = std::chrono::duration<double>(end_ - Clock::now()).count();
    return s > 0 ? s : 0.0;
  }
  /// The earlier of this deadline and `seconds` from now, same cancel flag and memory guard.
  Deadline within(double seconds) const {
    Deadline d = in(seconds, cancel_);
    if (end_ < d.end_) d.end_ = end_;
    d.memory_ = memory_;
    return d;
  }
  /// This deadline, also expired once `guard` trips (the guard must outlive the solve; null:
  /// no memory limit).
  Deadline withMemoryGuard(const MemoryGuard* guard) const {
    Deadline d = *this;
    d.memory_ = guard;
    return d;
  }
  Clock::time_point end() const { return end_; }
  const std::atomic<bool>* cancelFlag() const { return cancel_; }
  const MemoryGuard* memoryGuard() const { return memory_; }

 private:
  Clock::time_point end_;
  const std::atomic<bool>* cancel_ = nullptr;
  const MemoryGuard* memory_ = nullptr;
};

/// Thrown by work that has no partial result to return (building state graphs) when its deadline
/// passes first; callers report it as TIMEOUT (or CANCELLED, RESOURCE_LIMIT: see the deadline).
class DeadlineExpired : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace fleet_planner
