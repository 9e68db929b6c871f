#include "fleet_planner/runtime/memory_guard.h"

#include <algorithm>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "number_format.h"

namespace fleet_planner {

namespace {

// Resident memory after handing free heap pages back to the system.
double trimmedResidentMb() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
  return residentMemoryMb();
}

}  // namespace

bool MemoryGuard::sample(Clock::time_point now) const {
  next_sample_.store(now.time_since_epoch().count() + interval_, std::memory_order_relaxed);
  double rss = residentMemoryMb();
  if (rss > limit_mb_) rss = trimmedResidentMb();
  double peak = peak_mb_.load(std::memory_order_relaxed);
  while (rss > peak && !peak_mb_.compare_exchange_weak(peak, rss, std::memory_order_relaxed)) {
  }
  if (rss > limit_mb_) tripped_.store(true, std::memory_order_relaxed);
  return tripped_.load(std::memory_order_relaxed);
}

void MemoryGuard::reserve(double extra_mb, const std::string& what) const {
  double rss = residentMemoryMb();
  if (rss < 0) rss = 0;
  if (rss + extra_mb <= limit_mb_) return;
  rss = std::max(0.0, trimmedResidentMb());
  if (rss + extra_mb <= limit_mb_) return;
  throw ResourceLimitError(
      "max_memory_mb", what + " need an estimated " + io::formatMb(extra_mb) + " on top of the " + io::formatMb(rss) +
                           " in use, more than max_memory_mb=" + io::formatNumber(limit_mb_));
}

std::string MemoryGuard::reason() const {
  return "the process's resident memory reached " + io::formatMb(peakSampledMb()) +
         ", over max_memory_mb=" + io::formatNumber(limit_mb_);
}

}  // namespace fleet_planner
