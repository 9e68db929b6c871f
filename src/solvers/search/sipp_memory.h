#pragma once
// The safe interval search's types and the memory it keeps from one search to the next on a
// thread; private to safe_interval_search.cpp.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "fleet_planner/solvers/search/soft_path_table.h"
#include "fleet_planner/model/action.h"
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

// One state's answers so far in a search (SearchMemory::states).
struct StateAnswers {
  StateId s;
  std::array<int, kActions> unsafe;  // by action: index into SearchMemory::unsafe, -1: not asked
  PoolRun<Interval> intervals;       // its safe intervals, if `best` >= 0
  int best;  // its first entry in SearchMemory::best_of (one per interval); -1: intervals not asked
};

// What a search allocates, kept from one search to the next on the same thread: a parking
// plan makes thousands of searches, and allocating and first touching their memory anew each
// time cost about a tenth of its time. The answers are found through an array over every state
// id rather than a hash table: neighbouring states lie close in it, so a search's reads stay in
// the cache, where a hash spreads them over a table as large as the largest search so far.
struct SearchMemory {
  // Sipp's answers: state id -> index into states (-1: none), the answers by state in the
  // order asked, and the runs they point into.
  std::vector<int> state_index;
  std::vector<StateAnswers> states;
  std::vector<Unsafe> unsafe;
  StablePool<std::pair<int, int>> run_pool;
  StablePool<Interval> interval_pool;
  std::vector<std::pair<int, int>> merged, runs;  // Sipp's scratch
  std::vector<Interval> interval_scratch;
  // searchBetween's nodes, (state, interval) -> node (best_of, through StateAnswers::best; -1:
  // none), and open list (a heap of the nodes' f, g and index: its comparisons read the heap
  // alone).
  struct Open {
    int f, g, index;
  };
  std::vector<Node> nodes;
  std::vector<int> best_of;
  std::vector<Open> open;

  // Cleared for a search over `state_ids` state ids.
  void clear(int state_ids) {
    for (const StateAnswers& answers : states) state_index[answers.s] = -1;
    if (state_index.size() < static_cast<std::size_t>(state_ids)) state_index.resize(state_ids, -1);
    states.clear();
    unsafe.clear();
    run_pool.clear();
    interval_pool.clear();
    nodes.clear();
    best_of.clear();
    open.clear();
  }
  // Bytes held that grow with the searches made (the array over state ids grows with the map
  // alone, and is kept whatever its size: allocated anew for each search of a large map, it
  // would cost more than the search).
  std::size_t searchBytes() const {
    return states.capacity() * sizeof(StateAnswers) +
           run_pool.bytes() + interval_pool.bytes() + unsafe.capacity() * sizeof(Unsafe) +
           nodes.capacity() * sizeof(Node) + best_of.capacity() * sizeof(int) +
           open.capacity() * sizeof(Open);
  }
};

// The thread's SearchMemory for one search over `state_ids` state ids, cleared; a new one if the
// thread's is taken (or was dropped). Kept for the thread's next search unless it grew past
// kKeptBytes.
class MemoryLease {
 public:
  explicit MemoryLease(int state_ids) : held_(idle_ ? std::move(idle_) : std::make_unique<SearchMemory>()) {
    held_->clear(state_ids);
  }
  ~MemoryLease() {
    if (!idle_ && held_->searchBytes() <= kKeptBytes) idle_ = std::move(held_);
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
