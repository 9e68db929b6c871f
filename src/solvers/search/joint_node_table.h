#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fleet_planner {

/// The joint search's nodes by key (the members' states, the time, the members done): open
/// addressing over node indices, the key read from the node itself. A slot holds the key's
/// 64-bit hash besides the index, so a probe that misses seldom reads a node. One
/// allocation that doubles, instead of a heap node per entry: looking keys up was a third of
/// a joint search's time with std::unordered_map.
class JointNodeTable {
 public:
  JointNodeTable() : slots_(1 << 12) {}

  /// The entry of the key of hash `hash`: its index (`added` false), or a new entry holding -1
  /// (`added` true) for the caller to set. Valid until the next call.
  template <typename Same>
  int& entry(std::uint64_t hash, Same same, bool& added) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    std::size_t i = slot(hash);
    for (; slots_[i].index >= 0; i = next(i)) {
      if (slots_[i].hash == hash && same(slots_[i].index)) {
        added = false;
        return slots_[i].index;
      }
    }
    slots_[i].hash = hash;
    ++size_;
    added = true;
    return slots_[i].index;  // -1 until the caller sets it
  }

 private:
  struct Slot {
    std::uint64_t hash = 0;   // compared before the node's key; places the entry when the table grows
    std::int32_t index = -1;  // -1: empty
  };
  std::size_t slot(std::uint64_t hash) const { return static_cast<std::size_t>(hash) & (slots_.size() - 1); }
  std::size_t next(std::size_t i) const { return (i + 1) & (slots_.size() - 1); }
  void grow() {
    std::vector<Slot> old(slots_.size() * 2);
    old.swap(slots_);
    for (const Slot& s : old) {
      if (s.index < 0) continue;
      std::size_t i = slot(s.hash);
      while (slots_[i].index >= 0) i = next(i);
      slots_[i] = s;
    }
  }
  std::vector<Slot> slots_;
  std::size_t size_ = 0;
};

}  // namespace fleet_planner
