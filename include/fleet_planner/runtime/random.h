#pragma once
/// A small seeded random generator (SplitMix64) whose draws are the same on every platform and
/// standard library, unlike std::uniform_*_distribution. Every random choice in the library
/// comes from one of these, seeded by the caller.
#include <cstdint>

namespace fleet_planner {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  /// Uniform integer in [lo, hi] (lo <= hi).
  std::int64_t uniformInt(std::int64_t lo, std::int64_t hi) {
    const std::uint64_t span = static_cast<std::uint64_t>(hi - lo) + 1;
    if (span == 0) return static_cast<std::int64_t>(next());
    // Rejection sampling: no modulo bias.
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % span;
    std::uint64_t r;
    do {
      r = next();
    } while (r >= limit);
    return lo + static_cast<std::int64_t>(r % span);
  }
  /// Uniform double in [0, 1).
  double uniform01() { return static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0); }

 private:
  std::uint64_t state_;
};

}  // namespace fleet_planner
