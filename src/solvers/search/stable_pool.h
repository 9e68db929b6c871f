#pragma once
#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace fleet_planner {

/// A run of T stored in a StablePool: valid until the pool is cleared or destroyed.
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
    // The chunk being filled, else the next one kept from before a clear() that holds the
    // items, else a new one.
    while (current_ < chunks_.size() && used_ + n > capacities_[current_]) {
      ++current_;
      used_ = 0;
    }
    if (current_ == chunks_.size()) {
      capacities_.push_back(std::max(kChunk, n));
      chunks_.push_back(std::make_unique<T[]>(static_cast<std::size_t>(capacities_.back())));
      used_ = 0;
    }
    T* at = chunks_[current_].get() + used_;
    std::copy(items.begin(), items.end(), at);
    used_ += n;
    return {at, n};
  }
  /// Forgets every run (they become invalid), keeping the chunks for the next ones.
  void clear() {
    current_ = 0;
    used_ = 0;
  }
  /// Bytes held.
  std::size_t bytes() const {
    std::size_t n = 0;
    for (int c : capacities_) n += static_cast<std::size_t>(c) * sizeof(T);
    return n;
  }

 private:
  static constexpr int kChunk = 1 << 14;
  std::vector<std::unique_ptr<T[]>> chunks_;
  std::vector<int> capacities_;
  std::size_t current_ = 0;
  int used_ = 0;
};

}  // namespace fleet_planner
