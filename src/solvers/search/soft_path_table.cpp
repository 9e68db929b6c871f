#include "fleet_planner/solvers/search/soft_path_table.h"

#include <algorithm>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/solvers/search/space_time_astar.h"

namespace fleet_planner {

namespace {

constexpr int kBucketCells = 4;  // a bucket is 4 x 4 cells: a large robot's sweep spans a few

}  // namespace

SoftPathTable::SoftPathTable(const SearchSpace& space)
    : space_(space),
      width_(space.numAgents() > 0 ? space.graph(0).width() : 1),
      height_(space.numAgents() > 0 ? space.graph(0).height() : 1),
      bx_((width_ + kBucketCells - 1) / kBucketCells),
      by_((height_ + kBucketCells - 1) / kBucketCells),
      buckets_(bx_ * by_),
      paths_(space.numAgents()),
      agent_runs_(space.numAgents()),
      stamp_(space.numAgents(), 0) {}

std::uint64_t SoftPathTable::blockOf(int t) {
  return std::uint64_t{1} << std::min(t / kBlockSteps, 63);
}

std::uint64_t SoftPathTable::blocksOf(int first, int last) {
  const int b0 = std::min(first / kBlockSteps, 63), b1 = std::min(last / kBlockSteps, 63);
  const std::uint64_t upto = b1 == 63 ? ~std::uint64_t{0} : (std::uint64_t{1} << (b1 + 1)) - 1;
  return upto & ~((std::uint64_t{1} << b0) - 1);
}

SoftPathTable::Bucket SoftPathTable::bucketsOf(const CellSet& set, Cell origin) const {
  auto clampX = [&](int x) { return std::clamp(x, 0, width_ - 1) / kBucketCells; };
  auto clampY = [&](int y) { return std::clamp(y, 0, height_ - 1) / kBucketCells; };
  return {clampX(origin.x + set.minX()), clampY(origin.y + set.minY()),
          clampX(origin.x + set.maxX()), clampY(origin.y + set.maxY())};
}

template <class F>
void SoftPathTable::forBuckets(const CellSet& set, Cell origin, F&& f) const {
  if (set.empty()) return;
  const Bucket b = bucketsOf(set, origin);
  for (int y = b.y0; y <= b.y1; ++y) {
    for (int x = b.x0; x <= b.x1; ++x) f(y * bx_ + x);
  }
}

void SoftPathTable::index(int a, bool on) {
  const StatePath& path = paths_[a];
  const StateGraph& g = space_.graph(a);
  auto edit = [&](std::vector<int>& agents) {
    if (on) {
      agents.push_back(a);
    } else {
      agents.erase(std::find(agents.begin(), agents.end(), a));
    }
  };
  // The steps during which a sweeps a cell, one span per stretch of consecutive steps.
  std::vector<int> touched;  // cells whose spans name a (removal)
  auto span = [&](int cell, int t, int last) {
    std::vector<Span>& spans = cell_spans_[cell];
    if (!on) {
      touched.push_back(cell);
      return;
    }
    if (!spans.empty() && spans.back().agent == a && spans.back().last == t - 1) {
      spans.back().last = last;
    } else {
      spans.push_back({t, last, a});
    }
    cell_blocks_[cell] |= blocksOf(t, last);
  };
  for (int t = 0; t + 1 < static_cast<int>(path.size()); ++t) {
    const GridPose p = g.pose(path[t]);
    const Action act = stepAction(g, path[t], path[t + 1]);
    const CellSet& swept = space_.cells(a).swept(p.heading, act);
    forBuckets(swept, {p.x, p.y}, [&](int bucket) {
      std::vector<Motion>& motions = moving_[key(t, bucket)];
      if (on) {
        motions.push_back({a, p, act});
      } else {
        motions.erase(std::find_if(motions.begin(), motions.end(), [a](const Motion& m) { return m.agent == a; }));
      }
      if (motions.empty()) moving_.erase(key(t, bucket));
    });
    forEachMapCell(swept, {p.x, p.y}, width_, height_, [&](int cell) { span(cell, t, t); });
  }
  const GridPose end = g.pose(path.back());
  const CellSet& body = space_.cells(a).body(end.heading);
  forBuckets(body, {end.x, end.y}, [&](int bucket) { edit(parked_[bucket]); });
  const int parked_from = static_cast<int>(path.size()) - 1;
  forEachMapCell(body, {end.x, end.y}, width_, height_, [&](int cell) { span(cell, parked_from, kNever); });
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  for (int cell : touched) {
    std::vector<Span>& spans = cell_spans_[cell];
    spans.erase(std::remove_if(spans.begin(), spans.end(), [a](const Span& r) { return r.agent == a; }),
                spans.end());
    std::uint64_t blocks = 0;
    for (const Span& r : spans) blocks |= blocksOf(r.first, r.last);
    cell_blocks_[cell] = blocks;
  }
}

void SoftPathTable::insert(int a, const StatePath& path) {
  if (cell_spans_.empty()) {
    parked_.resize(buckets_);
    cell_spans_.resize(static_cast<std::size_t>(width_) * height_);
    cell_blocks_.assign(cell_spans_.size(), 0);
  }
  paths_[a] = path;
  index(a, true);
}

void SoftPathTable::remove(int a) {
  index(a, false);
  paths_[a].clear();
}

int SoftPathTable::lastMove() const {
  int last = -1;
  for (const StatePath& p : paths_) last = std::max(last, static_cast<int>(p.size()) - 2);
  return last;
}

bool SoftPathTable::meets(int a, const GridPose& p, Action action, int b, const GridPose& q,
                          Action b_action) const {
  return sweepsOverlap(space_.cells(a), p, action, space_.cells(b), q, b_action);
}

bool SoftPathTable::hits(int a, const GridPose& p, Action action, int b, int t) const {
  const StateGraph& g = space_.graph(b);
  const StateId s = stateAt(paths_[b], t), n = stateAt(paths_[b], t + 1);
  return meets(a, p, action, b, g.pose(s), stepAction(g, s, n));
}

void SoftPathTable::newQuery() const {
  if (++query_ == 0) {  // wrapped: forget every stamp
    std::fill(stamp_.begin(), stamp_.end(), 0);
    query_ = 1;
  }
}

bool SoftPathTable::firstVisit(int b) const {
  if (stamp_[b] == query_) return false;
  stamp_[b] = query_;
  return true;
}

void SoftPathTable::collisions(int a, StateId s, Action action, int t,
                               std::vector<int>& out) const {
  if (cell_spans_.empty()) return;
  newQuery();
  stamp_[a] = query_;
  const GridPose p = space_.graph(a).pose(s);
  // Every agent whose sweep during step t (its body, once it has ended) meets a's sweep covers
  // a cell of a's probe during t.
  const std::uint64_t block = blockOf(t);
  forEachMapCell(space_.probe(a, p.heading, action), {p.x, p.y}, width_, height_, [&](int cell) {
    if (!(cell_blocks_[cell] & block)) return;
    for (const Span& r : cell_spans_[cell]) {
      if (r.first <= t && t <= r.last && firstVisit(r.agent)) out.push_back(r.agent);
    }
  });
}

void SoftPathTable::collisionsHolding(int a, StateId s, int t, std::vector<int>& out) const {
  if (cell_spans_.empty()) return;
  newQuery();
  stamp_[a] = query_;
  const GridPose p = space_.graph(a).pose(s);
  const CellSet& body = space_.cells(a).body(p.heading);
  const int last = lastMove();
  forBuckets(body, {p.x, p.y}, [&](int bucket) {
    // Here an agent is marked only once met: one that misses standing at its end may still
    // meet a while it moves, at another step.
    auto met = [&](int b) {
      stamp_[b] = query_;
      out.push_back(b);
    };
    for (int b : parked_[bucket]) {
      const int end = static_cast<int>(paths_[b].size());
      if (stamp_[b] != query_ && hits(a, p, Action::Wait, b, end)) met(b);
    }
    for (int step = t; step <= last; ++step) {
      const auto it = moving_.find(key(step, bucket));
      if (it == moving_.end()) continue;
      for (const Motion& m : it->second) {
        if (stamp_[m.agent] != query_ && meets(a, p, Action::Wait, m.agent, m.pose, m.action)) met(m.agent);
      }
    }
  });
}

void SoftPathTable::unsafeRuns(int a, StateId s, Action action,
                               std::vector<std::pair<int, int>>& runs, int& forever_from) const {
  runs.clear();
  forever_from = kNever;
  if (cell_spans_.empty()) return;
  newQuery();
  met_.clear();
  const GridPose p = space_.graph(a).pose(s);
  // Neighbouring cells mostly hold the same pass of an agent, give or take a step: the spans
  // of each agent are merged as they come, so the caller sorts one run per pass, not per cell.
  // The probe of the sweep meets every agent's sweep (or body) the sweep meets.
  forEachMapCell(space_.probe(a, p.heading, action), {p.x, p.y}, width_, height_, [&](int cell) {
    for (const Span& r : cell_spans_[cell]) {
      if (r.agent == a) continue;
      if (r.last == kNever) {
        forever_from = std::min(forever_from, r.first);
        continue;
      }
      std::vector<std::pair<int, int>>& mine = agent_runs_[r.agent];
      if (firstVisit(r.agent)) {
        mine.clear();
        met_.push_back(r.agent);
      }
      bool merged = false;
      for (auto& run : mine) {
        if (r.first <= run.second + 1 && run.first <= r.last + 1) {
          run = {std::min(run.first, r.first), std::max(run.second, r.last)};
          merged = true;
          break;
        }
      }
      if (!merged) mine.emplace_back(r.first, r.last);
    }
  });
  for (int b : met_) runs.insert(runs.end(), agent_runs_[b].begin(), agent_runs_[b].end());
}

std::vector<int> SoftPathTable::partners(int a, const StatePath& path) const {
  std::vector<int> out, step;
  if (path.empty()) return out;
  const StateGraph& g = space_.graph(a);
  const int until = std::max(static_cast<int>(path.size()) - 1, lastMove() + 1);
  for (int t = 0; t <= until; ++t) {
    const StateId s = stateAt(path, t), n = stateAt(path, t + 1);
    step.clear();
    collisions(a, s, stepAction(g, s, n), t, step);
    out.insert(out.end(), step.begin(), step.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace fleet_planner
