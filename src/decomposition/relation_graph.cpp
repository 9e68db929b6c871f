// Component connectivity graphs; see relation_graph.h (paper: Preliminaries, "Cluster and
// level" for r_s / r_t, and "Component connectivity graph").
#include "fleet_planner/decomposition/relation_graph.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <unordered_map>

namespace fleet_planner {

namespace {

constexpr Action kMoves[] = {Action::Forward, Action::Backward, Action::RotateCcw, Action::RotateCw};

// What Tarjan's search reads and writes per state, in one record: one cache line per visit.
struct Visit {
  std::int32_t rel = 0;     // relation id (0 = unrelated)
  std::int32_t index = -1;  // DFS order; -1 = not visited
  std::int32_t low = 0;
  std::int32_t comp = -1;   // component; -1 while on the stack
};

// Per-thread arrays over state ids, reused from graph to graph (and left clean after each).
struct Scratch {
  std::vector<Visit> visit;
  std::vector<std::int32_t> stamp, count;
  std::vector<StateId> stack;
  std::vector<std::pair<StateId, int>> calls;
  void resize(std::size_t n) {
    if (stamp.size() >= n) return;
    visit.assign(n, Visit{});
    stamp.assign(n, -1);
    count.assign(n, 0);
  }
};

class Builder {
 public:
  // The graph of the robots `users` (one graph).
  Builder(const Instance& instance, const FleetGraphs& graphs, const std::vector<int>& users, Scratch& s)
      : instance_(instance), graphs_(graphs), g_(graphs.graph(users.front())), cells_(graphs.cells(users.front())), s_(s),
        step_(g_.actionModel().step), used_offset_(static_cast<std::size_t>(step_ * step_), 0) {
    s_.resize(g_.stateIdCount());
    for (int i : users) {
      for (const GridPose& p : {instance.robots[i].start, instance.robots[i].target}) used_offset_[offset(p)] = 1;
    }
  }

  std::shared_ptr<ComponentGraph> build() {
    relate();
    components();
    return assemble();
  }
  int componentOf(StateId s) const { return s_.visit[s].comp; }

  // Leaves the scratch arrays as found.
  void reset() {
    for (StateId u : touched_) {
      s_.count[u] = 0;
      s_.stamp[u] = -1;
    }
    std::fill(s_.visit.begin(), s_.visit.begin() + g_.stateIdCount(), Visit{});
  }

 private:
  // Every (state, SAT) relation, SATs in increasing order; then one id per distinct SAT list.
  void relate() {
    const int n = static_cast<int>(instance_.robots.size());
    for (int sat = 0; sat < 2 * n; ++sat) {
      const Robot& other = instance_.robots[sat / 2];
      const GridPose& p = sat % 2 == 0 ? other.start : other.target;
      const CellSet& taken = graphs_.cells(sat / 2).body(p.heading);
      for (int h = 0; h < kHeadings; ++h) {
        markOverlaps(taken, p, cells_.body(h), h, sat, kNoAction);
        // A move sweeps only its two footprints, each related on its own; a rotation sweeps
        // more, so a state is also related to what its rotations sweep (its reverse rotation,
        // with the same sweep, relates the state it turns to).
        // On a lattice (step > 1) a move also sweeps the footprints between its two states:
        // the state it leaves is related to those too (every path over the move visits it).
        for (Action a : {Action::RotateCcw, Action::RotateCw, Action::Forward, Action::Backward}) {
          if ((a == Action::Forward || a == Action::Backward) && cells_.step() == 1) continue;
          markOverlaps(taken, p, cells_.swept(h, a), h, sat, a);
        }
      }
    }
    // Group the pairs by state (counting sort, stable: each state's SATs stay ascending).
    std::vector<std::int32_t> begin(touched_.size() + 1, 0);
    for (std::size_t k = 0; k < touched_.size(); ++k) begin[k + 1] = begin[k] + s_.count[touched_[k]];
    for (std::size_t k = 0; k < touched_.size(); ++k) s_.count[touched_[k]] = static_cast<std::int32_t>(k);  // slot
    std::vector<std::int32_t> fill(begin.begin(), begin.end() - 1), grouped(pairs_.size());
    for (const auto& [u, sat] : pairs_) grouped[fill[s_.count[u]]++] = sat;
    // Intern the lists: relation id 0 = unrelated, k = rel_sats_[k].
    std::unordered_map<std::uint64_t, std::vector<int>> by_hash;
    rel_sats_.assign(1, {});
    for (std::size_t k = 0; k < touched_.size(); ++k) {
      const auto first = grouped.begin() + begin[k], last = grouped.begin() + begin[k + 1];
      std::uint64_t h = 1469598103934665603ULL;
      for (auto it = first; it != last; ++it) h = (h ^ static_cast<std::uint64_t>(*it)) * 1099511628211ULL;
      int id = -1;
      for (int candidate : by_hash[h]) {
        if (std::equal(first, last, rel_sats_[candidate].begin(), rel_sats_[candidate].end())) id = candidate;
      }
      if (id < 0) {
        id = static_cast<int>(rel_sats_.size());
        rel_sats_.emplace_back(first, last);
        by_hash[h].push_back(id);
      }
      s_.visit[touched_[k]].rel = id;
    }
  }

  // Marks with `sat` every state at heading h whose `own` cells (relative to the state; those of
  // action `a` when a is not kNoAction, for states that allow it) overlap `other` placed at `at`.
  // Row by row: a run of `other` and a run of `own` overlap for one range of x on one row, so the
  // states form a few ranges per row, merged before marking (a cell-by-cell Minkowski sum of two
  // 300-cell footprints was most of the decomposition's time on fine maps).
  void markOverlaps(const CellSet& other, const GridPose& at, const CellSet& own, int h, int sat, Action a) {
    ranges_.clear();
    for (const auto& r : other.runs()) {
      for (const auto& q : own.runs()) {
        ranges_.push_back({at.y + r.dy - q.dy, at.x + r.x0 - q.x1, at.x + r.x1 - q.x0});
      }
    }
    std::sort(ranges_.begin(), ranges_.end());
    for (std::size_t i = 0; i < ranges_.size();) {
      Range merged = ranges_[i];
      for (++i; i < ranges_.size() && ranges_[i].y == merged.y && ranges_[i].x0 <= merged.x1 + 1; ++i) {
        merged.x1 = std::max(merged.x1, ranges_[i].x1);
      }
      for (int x = merged.x0; x <= merged.x1; ++x) {
        const StateId u = g_.id({x, merged.y, h});
        if (u != kNoState && (a == kNoAction || g_.allows(u, a))) mark(u, sat);
      }
    }
  }

  void mark(StateId u, int sat) {
    if (u == kNoState || !g_.valid(u) || s_.stamp[u] == sat) return;
    if (s_.stamp[u] < 0) touched_.push_back(u);
    s_.stamp[u] = sat;
    ++s_.count[u];
    pairs_.push_back({u, sat});
  }

  // The index of a pose's lattice offset (x and y modulo the step).
  int offset(const GridPose& p) const { return (p.y % step_) * step_ + p.x % step_; }
  // A state of a lattice that one of the graph's robots stands on: a move keeps a state on its
  // lattice, so the components of the other lattices are never reached from the robots' own.
  bool used(StateId u) const { return step_ == 1 || used_offset_[offset(g_.pose(u))]; }

  // Tarjan's strongly connected components, iterative, over edges within one relation id, on
  // the robots' lattices.
  void components() {
    int counter = 0;
    std::vector<Visit>& vis = s_.visit;
    for (StateId root = 0; root < g_.stateIdCount(); ++root) {
      if (!g_.valid(root) || vis[root].index >= 0 || !used(root)) continue;
      open(root, counter);
      while (!s_.calls.empty()) {
        const StateId u = s_.calls.back().first;
        bool descended = false;
        while (s_.calls.back().second < 4) {
          const Action a = kMoves[s_.calls.back().second++];
          if (!g_.allows(u, a)) continue;
          const StateId v = g_.next(u, a);
          const Visit& w = vis[v];
          if (w.rel != vis[u].rel) continue;
          if (w.index < 0) {
            open(v, counter);
            descended = true;
            break;
          }
          if (w.comp < 0) vis[u].low = std::min(vis[u].low, w.index);  // still on the stack
        }
        if (descended) continue;
        if (vis[u].low == vis[u].index) {
          StateId x;
          do {
            x = s_.stack.back();
            s_.stack.pop_back();
            vis[x].comp = num_comps_;
          } while (x != u);
          comp_rel_.push_back(vis[u].rel);
          ++num_comps_;
        }
        s_.calls.pop_back();
        if (!s_.calls.empty()) {
          const StateId parent = s_.calls.back().first;
          vis[parent].low = std::min(vis[parent].low, vis[u].low);
        }
      }
    }
  }

  void open(StateId v, int& counter) {
    s_.visit[v].index = s_.visit[v].low = counter++;
    s_.stack.push_back(v);
    s_.calls.push_back({v, 0});
  }

  std::shared_ptr<ComponentGraph> assemble() {
    auto out = std::make_shared<ComponentGraph>();
    for (int c = 0; c < num_comps_; ++c) {
      const auto& list = rel_sats_[comp_rel_[c]];
      out->sats.insert(out->sats.end(), list.begin(), list.end());
      out->sat_begin.push_back(static_cast<std::int32_t>(out->sats.size()));
    }
    // Edges between components, in one sequential pass.
    std::vector<std::pair<std::int32_t, std::int32_t>> cross;
    for (StateId u = 0; u < g_.stateIdCount(); ++u) {
      if (!g_.valid(u) || !used(u)) continue;
      const std::int32_t cu = s_.visit[u].comp;
      g_.forEachSuccessor(u, [&](Action, StateId v) {
        if (s_.visit[v].comp != cu) cross.push_back({cu, s_.visit[v].comp});
      });
    }
    std::sort(cross.begin(), cross.end());
    cross.erase(std::unique(cross.begin(), cross.end()), cross.end());
    std::size_t k = 0;
    for (int c = 0; c < num_comps_; ++c) {
      for (; k < cross.size() && cross[k].first == c; ++k) out->edges.push_back(cross[k].second);
      out->edge_begin.push_back(static_cast<std::int32_t>(out->edges.size()));
    }
    return out;
  }

  const Instance& instance_;
  const FleetGraphs& graphs_;
  const StateGraph& g_;
  const FootprintCells& cells_;
  Scratch& s_;
  const int step_;
  std::vector<char> used_offset_;  // by offset(): a robot of the graph stands on that lattice
  struct Range {
    int y, x0, x1;
    bool operator<(const Range& o) const { return y != o.y ? y < o.y : x0 < o.x0; }
  };
  static constexpr Action kNoAction = Action::Wait;  // markOverlaps: the body, no action
  std::vector<Range> ranges_;
  std::vector<StateId> touched_;
  std::vector<std::pair<StateId, int>> pairs_;
  std::vector<std::vector<int>> rel_sats_;
  std::vector<int> comp_rel_;
  int num_comps_ = 0;
};

}  // namespace

std::vector<RelationGraph> buildRelationGraphs(const Instance& instance, const FleetGraphs& graphs, int threads,
                                               const Deadline& deadline) {
  const int n = static_cast<int>(instance.robots.size());
  std::vector<std::vector<int>> users(graphs.numGraphs());
  for (int i = 0; i < n; ++i) users[graphs.graphIndex(i)].push_back(i);
  std::vector<RelationGraph> out(n);
  std::atomic<int> next{0};
  auto worker = [&] {
    Scratch scratch;
    for (int k = next++; k < graphs.numGraphs(); k = next++) {
      if (users[k].empty()) continue;
      if (deadline.expired()) break;  // a component graph takes up to a few hundred ms on a large map
      Builder builder(instance, graphs, users[k], scratch);
      const std::shared_ptr<const ComponentGraph> shared = builder.build();
      for (int i : users[k]) {
        const StateGraph& g = graphs.graph(i);
        out[i] = {shared, i, builder.componentOf(g.id(instance.robots[i].start)),
                  builder.componentOf(g.id(instance.robots[i].target))};
      }
      builder.reset();
    }
  };
  const int t = std::max(1, std::min(threads, graphs.numGraphs()));
  std::vector<std::thread> pool;
  for (int k = 1; k < t; ++k) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  return out;
}

}  // namespace fleet_planner
