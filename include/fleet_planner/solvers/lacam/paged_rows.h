#pragma once
/// Rows of a fixed width (one per search node: a configuration, an agent order, priorities),
/// appended and never moved: they live in pages of a power-of-two number of rows, so that a
/// search of millions of nodes grows without copying what it already holds (a growing vector
/// copies all of it at every doubling) and a row is found with a shift and a mask.
#include <cstddef>
#include <memory>
#include <vector>

namespace fleet_planner {

template <class T>
class PagedRows {
 public:
  /// `width`: entries per row (at least 1). Pages hold about kPageBytes.
  explicit PagedRows(int width) : width_(static_cast<std::size_t>(width < 1 ? 1 : width)) {
    while ((std::size_t{2} << shift_) * width_ * sizeof(T) <= kPageBytes) ++shift_;
    mask_ = (std::size_t{1} << shift_) - 1;
  }

  /// Storage of a new row, uninitialised; the caller fills its `width` entries.
  T* append() {
    if ((size_ & mask_) == 0 && (size_ >> shift_) == pages_.size()) {
      pages_.emplace_back(new T[width_ << shift_]);
    }
    T* row = pages_[size_ >> shift_].get() + (size_ & mask_) * width_;
    ++size_;
    return row;
  }

  const T* row(std::size_t i) const { return pages_[i >> shift_].get() + (i & mask_) * width_; }
  std::size_t size() const { return size_; }
  /// Bytes held by the pages.
  double bytes() const {
    return static_cast<double>(pages_.size()) * static_cast<double>(width_ << shift_) * sizeof(T);
  }

 private:
  // Small enough for the heap (no system call per page), so that the many tiny searches of
  // pair proofs stay cheap.
  static constexpr std::size_t kPageBytes = std::size_t{1} << 16;
  std::size_t width_;
  std::size_t shift_ = 0;  // a page holds 2^shift_ rows
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
  std::vector<std::unique_ptr<T[]>> pages_;
};

}  // namespace fleet_planner
