#pragma once
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace fleet_planner {

/// Search key (a state with its time, interval or flags, packed in 64 bits; never ~0) -> node
/// index, open addressing: one allocation, freed at once when the deadline comes (a
/// node-per-entry hash map of millions of nodes takes most of a second). Shared by the
/// space-time searches of the backends.
class NodeTable {
 public:
  NodeTable() : slots_(1 << 12, {~0ULL, -1}) {}
  int* find(std::uint64_t key) {
    for (std::size_t i = slot(key);; i = (i + 1) & (slots_.size() - 1)) {
      if (slots_[i].first == key) return &slots_[i].second;
      if (slots_[i].second < 0) return nullptr;
    }
  }
  /// Empties the table, keeping its allocation: costs the entries set since the last clear.
  void clear() {
    for (std::uint32_t i : used_) slots_[i] = {~0ULL, -1};
    used_.clear();
    size_ = 0;
  }
  /// Bytes held.
  std::size_t bytes() const { return slots_.capacity() * sizeof(slots_[0]) + used_.capacity() * sizeof(used_[0]); }
  /// The entry of `key`; if there is none, one added with `node` (`added` says which).
  int& findOrAdd(std::uint64_t key, int node, bool& added) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    std::size_t i = slot(key);
    for (; slots_[i].second >= 0; i = (i + 1) & (slots_.size() - 1)) {
      if (slots_[i].first == key) {
        added = false;
        return slots_[i].second;
      }
    }
    slots_[i] = {key, node};
    used_.push_back(static_cast<std::uint32_t>(i));
    ++size_;
    added = true;
    return slots_[i].second;
  }
  void set(std::uint64_t key, int node) {
    if (int* existing = find(key)) {
      *existing = node;
      return;
    }
    if (2 * (size_ + 1) > slots_.size()) grow();
    place(key, node);
    ++size_;
  }

 private:
  std::size_t slot(std::uint64_t key) const { return (key * 0x9e3779b97f4a7c15ULL >> 20) & (slots_.size() - 1); }
  void place(std::uint64_t key, int node) {
    std::size_t i = slot(key);
    while (slots_[i].second >= 0) i = (i + 1) & (slots_.size() - 1);
    slots_[i] = {key, node};
    used_.push_back(static_cast<std::uint32_t>(i));
  }
  void grow() {
    std::vector<std::pair<std::uint64_t, int>> old(slots_.size() * 2, {~0ULL, -1});
    old.swap(slots_);
    used_.clear();
    for (const auto& [key, node] : old) {
      if (node >= 0) place(key, node);
    }
  }
  std::vector<std::pair<std::uint64_t, int>> slots_;
  std::vector<std::uint32_t> used_;  // the slots set, for clear()
  std::size_t size_ = 0;
};

}  // namespace fleet_planner
