#pragma once
// The safe interval search's types and the memory it keeps from one search to the next on a
// thread; private to safe_interval_search.cpp.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "fleet_planner/solvers/search/soft_path_table.h"
#include "node_table.h"
#include "stable_pool.h"

namespace fleet_planner {
namespace sipp_detail {

constexpr int kNever = SoftPathTable::kNever;

// Steps during which a motion collides: sorted, disjoint, non-adjacent intervals (inclusive;
// second == kNever: from first on).
using Unsafe = PoolRun<std::pair<int, int>>;

struct Interval {
  int first, last;  // steps during which waiting is safe, inclusive; last == kNever: for good
};

struct Node {
  StateId s;
  int interval;
  int last;  // the interval's last step (Interval::last)
  int g;     // arrival time
  int f;
  int parent;
  bool stale;  // a node of the same (state, interval) arriving earlier replaced it
};

// What a search allocates, kept from one search to the next on the same thread: a parking
// plan makes thousands of searches, and allocating and first touching their memory anew each
// time cost about a tenth of its time.
struct SearchMemory {
  // Sipp's answers so far, by (state, action) and by state: indices into unsafe and intervals.
  NodeTable unsafe_index, intervals_index;
  std::vector<Unsafe> unsafe;
  std::vector<PoolRun<Interval>> intervals;
  StablePool<std::pair<int, int>> run_pool;
  StablePool<Interval> interval_pool;
  std::vector<std::pair<int, int>> merged, runs;  // Sipp's scratch
  std::vector<Interval> interval_scratch;
  // searchBetween's nodes, (state, interval) -> node, and open list (a heap of the nodes' f, g
  // and index: its comparisons read the heap alone).
  struct Open {
    int f, g, index;
  };
  std::vector<Node> nodes;
  NodeTable best;
  std::vector<Open> open;

  void clear() {
    unsafe_index.clear();
    intervals_index.clear();
    best.clear();
    unsafe.clear();
    intervals.clear();
    run_pool.clear();
    interval_pool.clear();
    nodes.clear();
    open.clear();
  }
  std::size_t bytes() const {
    return unsafe_index.bytes() + intervals_index.bytes() + best.bytes() + run_pool.bytes() +
           interval_pool.bytes() + unsafe.capacity() * sizeof(Unsafe) +
           intervals.capacity() * sizeof(PoolRun<Interval>) + nodes.capacity() * sizeof(Node) +
           open.capacity() * sizeof(Open);
  }
};

// The thread's SearchMemory for one search, cleared; a new one if the thread's is taken (or
// was dropped). Kept for the thread's next search unless it grew past kKeptBytes.
class MemoryLease {
 public:
  MemoryLease() : held_(idle_ ? std::move(idle_) : std::make_unique<SearchMemory>()) { held_->clear(); }
  ~MemoryLease() {
    if (!idle_ && held_->bytes() <= kKeptBytes) idle_ = std::move(held_);
  }
  MemoryLease(const MemoryLease&) = delete;
  MemoryLease& operator=(const MemoryLease&) = delete;
  SearchMemory& memory() { return *held_; }

 private:
  static constexpr std::size_t kKeptBytes = std::size_t{64} << 20;
  std::unique_ptr<SearchMemory> held_;
  static thread_local std::unique_ptr<SearchMemory> idle_;
};

}  // namespace sipp_detail
}  // namespace fleet_planner
