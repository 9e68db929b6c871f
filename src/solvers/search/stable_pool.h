#pragma once
#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace fleet_planner {

/// A run of T stored in a StablePool: valid as long as the pool.
template <class T>
struct PoolRun {
  const T* data = nullptr;
  int count = 0;
  const T* begin() const { return data; }
  const T* end() const { return data + count; }
  bool empty() const { return count == 0; }
  int size() const { return count; }
  const T& operator[](int i) const { return data[i]; }
  const T& back() const { return data[count - 1]; }
};

/// Append-only storage of contiguous runs of T in large chunks: a stored run never moves, so a
/// search may cache thousands of small lists (its safe intervals) without an allocation each.
template <class T>
class StablePool {
 public:
  PoolRun<T> add(const std::vector<T>& items) {
    const int n = static_cast<int>(items.size());
    if (chunks_.empty() || used_ + n > capacity_) {
      capacity_ = std::max(kChunk, n);
      chunks_.push_back(std::make_unique<T[]>(static_cast<std::size_t>(capacity_)));
      used_ = 0;
    }
    T* at = chunks_.back().get() + used_;
    std::copy(items.begin(), items.end(), at);
    used_ += n;
    return {at, n};
  }

 private:
  static constexpr int kChunk = 1 << 14;
  std::vector<std::unique_ptr<T[]>> chunks_;
  int used_ = 0, capacity_ = 0;
};

}  // namespace fleet_planner
