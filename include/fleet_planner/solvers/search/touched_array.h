#pragma once
#include <cstddef>
#include <vector>

namespace fleet_planner {

/// Values per state id, all `empty` after reset(), for searches that touch few of a large
/// graph's states (a real map at 5 cm has a million state ids): a reset costs the entries set
/// since the last one, not the graph, and reuses the allocation.
template <class T>
class TouchedArray {
 public:
  void reset(std::size_t n, T empty) {
    if (values_.size() != n || empty_ != empty) {
      values_.assign(n, empty);
      touched_.clear();
      empty_ = empty;
      return;
    }
    for (std::size_t i : touched_) values_[i] = empty_;
    touched_.clear();
  }
  T operator[](std::size_t i) const { return values_[i]; }
  void set(std::size_t i, T value) {
    if (values_[i] == empty_) touched_.push_back(i);
    values_[i] = value;
  }

 private:
  std::vector<T> values_;
  std::vector<std::size_t> touched_;
  T empty_{};
};

}  // namespace fleet_planner
