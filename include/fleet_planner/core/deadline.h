#pragma once
/// When a solve must stop: a point in time and an optional cancel flag. Every solver checks it
/// in its loops and returns promptly (TIMEOUT or CANCELLED) once it has passed.
#include <atomic>
#include <chrono>
#include <limits>

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
  /// Cancelled or out of time.
  bool expired() const { return cancelled() || timedOut(); }
  /// Seconds left (infinity without a limit, 0 once passed).
  double remaining() const {
    if (end_ == Clock::time_point::max()) return std::numeric_limits<double>::infinity();
    const double s = std::chrono::duration<double>(end_ - Clock::now()).count();
    return s > 0 ? s : 0.0;
  }
  /// The earlier of this deadline and `seconds` from now, same cancel flag.
  Deadline within(double seconds) const {
    Deadline d = in(seconds, cancel_);
    if (end_ < d.end_) d.end_ = end_;
    return d;
  }
  Clock::time_point end() const { return end_; }
  const std::atomic<bool>* cancelFlag() const { return cancel_; }

 private:
  Clock::time_point end_;
  const std::atomic<bool>* cancel_ = nullptr;
};

}  // namespace fleet_planner
