// LA-LaCAM; see la_lacam.h for the references.
#include "fleet_planner/solvers/lacam/la_lacam.h"

#include <algorithm>

#include "fleet_planner/solvers/lacam/la_pibt.h"
#include "fleet_planner/solvers/lacam/paged_rows.h"
#include "fleet_planner/solvers/registry.h"
#include "fleet_planner/solvers/search/solve_common.h"

namespace fleet_planner {

namespace {

const bool kRegistered = registerSolver("la_lacam", [] { return std::make_unique<LaLacam>(); });

// A low-level constraint: `who` goes to `where` next; chained to its parent constraint, which
// lives in the same high-level node's tree.
struct LowNode {
  int parent;
  int who;
  StateId where;
  int depth;
};

// A configuration's search node. Its configuration, agent order and priorities live in paged
// rows of the search (n entries per node), so that a search of millions of nodes is a few
// allocations per thousand nodes, never copied, freed at once when the deadline comes.
struct HighNode {
  int parent;
  std::vector<LowNode> tree;  // breadth-first: nodes before `head` have been tried
  std::size_t head = 0;
};

class LacamSearch {
 public:
  LacamSearch(const SearchSpace& space, const Subproblem& problem, const LaLacamOptions& options)
      : space_(space),
        problem_(problem),
        options_(options),
        n_(space.numAgents()),
        pibt_(space, problem.seed),
        configs_(n_),
        orders_(n_),
        priorities_(n_) {
    table_.assign(1024, -1);
  }

  SolveResult run() {
    Config start(n_), goal(n_);
    for (int a = 0; a < n_; ++a) {
      start[a] = space_.start(a);
      goal[a] = space_.target(a);
    }
    std::vector<float> priority(n_);
    for (int a = 0; a < n_; ++a) {
      // Farther agents first; the fraction keeps the order among equals deterministic.
      priority[a] = static_cast<float>(space_.distance(a, start[a])) / static_cast<float>(1 + maxDistance(start));
    }
    addNode(start, hashOf(start.data()), -1, priority);
    std::vector<int> open{0};

    std::vector<std::pair<int, StateId>> fixed;
    Config current(n_), next;
    long long iterations = 0;
    while (!open.empty()) {
      if (problem_.deadline.expired() || ((++iterations & 15) == 0 && memoryMb() > options_.max_memory_mb)) {
        if (problem_.deadline.cancelled()) return failure(SolveStatus::Cancelled, "cancelled");
        if (problem_.deadline.timedOut()) return failure(SolveStatus::Timeout, "time limit reached");
        out_of_memory_ = true;
        return failure(SolveStatus::Timeout, "search reached its memory limit of " +
                                                 std::to_string(static_cast<int>(options_.max_memory_mb)) + " MB");
      }
      if (problem_.max_expansions >= 0 && stats_.low_level_expansions > problem_.max_expansions) {
        return failure(SolveStatus::Timeout,
                       "expansion budget of " + std::to_string(problem_.max_expansions) + " used up");
      }
      const int id = open.back();
      std::copy_n(configOf(id), n_, current.begin());
      if (current == goal) return success(id);
      if (nodes_[id].head == nodes_[id].tree.size()) {
        open.pop_back();
        release(nodes_[id]);
        continue;
      }
      const int low = static_cast<int>(nodes_[id].head++);
      ++stats_.low_level_expansions;
      if (nodes_[id].tree[low].depth < n_) expandLow(id, low, current);

      fixed.clear();
      const std::vector<LowNode>& tree = nodes_[id].tree;
      for (int c = low; tree[c].who >= 0; c = tree[c].parent) fixed.push_back({tree[c].who, tree[c].where});
      std::reverse(fixed.begin(), fixed.end());
      order_.assign(orders_.row(id), orders_.row(id) + n_);
      if (!pibt_.generate(current, fixed, order_, next)) continue;

      const std::size_t hash = hashOf(next.data());
      const int known = find(next, hash);
      if (known >= 0) {
        // Revisit: continue that node's remaining constraints; now and then (seeded) go back to
        // the start instead, so that a dead end's large subtree does not hold the search
        // (the restart rate of Okumura's lacam2/lacam3).
        open.push_back(pibt_.rng().uniform01() < options_.restart_rate ? 0 : known);
        continue;
      }
      std::vector<float>& p = priority_;
      p.assign(priorities_.row(id), priorities_.row(id) + n_);
      // PIBT's priorities: agents away from their target gain one per step; arrived ones drop back.
      for (int a = 0; a < n_; ++a) p[a] = next[a] == goal[a] ? p[a] - static_cast<float>(static_cast<int>(p[a])) : p[a] + 1;
      open.push_back(addNode(next, hash, id, p));
    }
    return failure(SolveStatus::Infeasible, "every reachable configuration explored: no conflict-free plan");
  }

  SolveStats stats() const { return stats_; }
  bool outOfMemory() const { return out_of_memory_; }
  double peakMemoryMb() const { return memoryMb(); }

 private:
  const StateId* configOf(int id) const { return configs_.row(static_cast<std::size_t>(id)); }

  // FNV-1a in four independent lanes (agents a, a + 4, ...), combined at the end: a quarter of
  // the single chain's multiplications in a row.
  std::size_t hashOf(const StateId* c) const {
    std::size_t h[4] = {1469598103934665603ULL, 0x9e3779b97f4a7c15ULL, 0xbf58476d1ce4e5b9ULL, 0x94d049bb133111ebULL};
    for (int a = 0; a < n_; ++a) {
      std::size_t& lane = h[a & 3];
      lane = (lane ^ static_cast<std::size_t>(static_cast<std::uint32_t>(c[a]))) * 1099511628211ULL;
    }
    return ((h[0] * 31 + h[1]) * 31 + h[2]) * 31 + h[3];
  }

  // Open addressing over node ids: one allocation however many configurations. Each node's
  // hash is kept (hashes_), so that a probe compares configurations only when the hashes match
  // and growing the table reads no configuration.
  int find(const Config& c, std::size_t hash) const {
    const std::size_t mask = table_.size() - 1;
    for (std::size_t i = hash & mask;; i = (i + 1) & mask) {
      const int id = table_[i];
      if (id < 0) return -1;
      if (hashes_[id] == hash && std::equal(c.begin(), c.end(), configOf(id))) return id;
    }
  }

  void insert(int id) {
    if (2 * (nodes_.size() + 1) > table_.size()) {
      std::vector<int> old(table_.size() * 2, -1);
      old.swap(table_);
      for (int existing : old) {
        if (existing >= 0) place(existing);
      }
    }
    place(id);
  }

  void place(int id) {
    const std::size_t mask = table_.size() - 1;
    std::size_t i = hashes_[id] & mask;
    while (table_[i] >= 0) i = (i + 1) & mask;
    table_[i] = id;
  }

  int maxDistance(const Config& c) const {
    int m = 0;
    for (int a = 0; a < n_; ++a) m = std::max(m, space_.distance(a, c[a]));
    return m;
  }

  int addNode(const Config& config, std::size_t hash, int parent, const std::vector<float>& priority) {
    const int id = static_cast<int>(nodes_.size());
    std::copy(config.begin(), config.end(), configs_.append());
    hashes_.push_back(hash);
    std::copy(priority.begin(), priority.end(), priorities_.append());
    // Agents by priority, highest first, ties by agent: sorted by insertion from the parent's
    // order, which the new priorities mostly keep.
    std::vector<int>& order = order_;
    if (parent < 0) {
      order.resize(n_);
      for (int a = 0; a < n_; ++a) order[a] = a;
    } else {
      order.assign(orders_.row(parent), orders_.row(parent) + n_);
    }
    auto before = [&](int x, int y) { return priority[x] != priority[y] ? priority[x] > priority[y] : x < y; };
    for (int i = 1; i < n_; ++i) {
      const int agent = order[i];
      int j = i;
      for (; j > 0 && before(agent, order[j - 1]); --j) order[j] = order[j - 1];
      order[j] = agent;
    }
    std::copy(order.begin(), order.end(), orders_.append());
    nodes_.push_back(HighNode{parent, {}, 0});
    // Room for the root constraint and one expansion's choices: one allocation, not four.
    nodes_.back().tree.reserve(1 + kActions);
    nodes_.back().tree.push_back(LowNode{-1, -1, kNoState, 0});
    ++live_low_;
    insert(id);
    ++stats_.high_level_nodes;
    return id;
  }

  void expandLow(int id, int low, const Config& current) {
    const int depth = nodes_[id].tree[low].depth;
    const int agent = orders_.row(id)[depth];
    StateChoices options = pibt_.candidates(agent, current[agent]);
    // Shuffle with the seed (Fisher-Yates) so that no direction is always tried first.
    for (int i = options.size(); i > 1; --i) {
      options.swap(i - 1, static_cast<int>(pibt_.rng().uniformInt(0, i - 1)));
    }
    for (int i = 0; i < options.size(); ++i) nodes_[id].tree.push_back({low, agent, options[i], depth + 1});
    live_low_ += static_cast<long long>(options.size());
  }

  // An exhausted node keeps its configuration (for duplicate detection) but not its tree.
  void release(HighNode& node) {
    live_low_ -= static_cast<long long>(node.tree.size());
    std::vector<LowNode>().swap(node.tree);
    node.head = 0;
  }

  // Live search memory: paged rows, nodes, the duplicate table, and the constraint trees
  // (counted at twice their size for vector growth).
  double memoryMb() const {
    const double flat = configs_.bytes() + orders_.bytes() + priorities_.bytes();
    const double nodes = static_cast<double>(nodes_.capacity()) * sizeof(HighNode) + table_.size() * sizeof(int) +
                         static_cast<double>(hashes_.capacity()) * sizeof(std::size_t);
    return (flat + nodes + 2.0 * static_cast<double>(live_low_) * sizeof(LowNode)) / 1048576.0;
  }

  SolveResult success(int id) {
    std::vector<StatePath> paths(n_);
    std::vector<int> chain;
    for (int i = id; i >= 0; i = nodes_[i].parent) chain.push_back(i);
    std::reverse(chain.begin(), chain.end());
    for (int i : chain) {
      for (int a = 0; a < n_; ++a) paths[a].push_back(configOf(i)[a]);
    }
    SolveResult r;
    r.status = SolveStatus::Success;
    r.paths = toPosePaths(space_, paths);
    return r;
  }

  SolveResult failure(SolveStatus status, std::string reason) const { return failedResult(status, std::move(reason)); }

  const SearchSpace& space_;
  const Subproblem& problem_;
  const LaLacamOptions& options_;
  const int n_;
  LaPibt pibt_;
  std::vector<HighNode> nodes_;
  PagedRows<StateId> configs_;
  PagedRows<int> orders_;
  PagedRows<float> priorities_;
  std::vector<int> order_;        // scratch: an agent order
  std::vector<float> priority_;   // scratch: a node's priorities
  std::vector<int> table_;
  std::vector<std::size_t> hashes_;  // per node: hashOf its configuration
  long long live_low_ = 0;
  bool out_of_memory_ = false;
  SolveStats stats_;
};

}  // namespace

SolveResult LaLacam::solve(const Subproblem& problem) {
  (void)kRegistered;
  return solveWith(problem, /*moving_allowed=*/false, [&](const SearchSpace& space, SolveStats& stats) {
    // When a search fills its memory budget, start afresh with another seed (its own
    // tie-breaking) until the deadline: memory stays bounded and the search goes on. Only an
    // exhausted first search proves infeasibility; restarts only ever end in success or time out.
    SolveResult r;
    Subproblem attempt = problem;
    for (int restart = 0;; ++restart) {
      attempt.seed = problem.seed + 0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(restart);
      LacamSearch search(space, attempt, options_);
      r = search.run();
      const SolveStats s = search.stats();
      stats.high_level_nodes += s.high_level_nodes;
      stats.low_level_expansions += s.low_level_expansions;
      stats.peak_memory_mb = std::max(stats.peak_memory_mb, search.peakMemoryMb());
      if (!search.outOfMemory() || problem.deadline.expired()) break;
    }
    return r;
  });
}

}  // namespace fleet_planner
