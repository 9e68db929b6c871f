#include "fleet_planner/solvers/search/soft_path_table.h"

#include <algorithm>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/solvers/search/space_time_astar.h"

namespace fleet_planner {

SoftPathTable::SoftPathTable(const SearchSpace& space)
    : space_(space),
      width_(space.numAgents() > 0 ? space.graph(0).width() : 1),
      height_(space.numAgents() > 0 ? space.graph(0).height() : 1),
      paths_(space.numAgents()),
      agent_runs_(space.numAgents()),
      stamp_(space.numAgents(), 0) {}

std::uint64_t SoftPathTable::blockOf(int t) {
  return std::uint64_t{1} << std::min(t / kBlockSteps, 63);
}

namespace {

// Bits b0..b1 of a word (0 <= b0 <= b1 <= 63).
std::uint64_t bitRange(int b0, int b1) {
  const std::uint64_t upto = b1 == 63 ? ~std::uint64_t{0} : (std::uint64_t{1} << (b1 + 1)) - 1;
  return upto & ~((std::uint64_t{1} << b0) - 1);
}

}  // namespace

std::uint64_t SoftPathTable::blocksOf(int first, int last) {
  return bitRange(std::min(first / kBlockSteps, 63), std::min(last / kBlockSteps, 63));
}

void SoftPathTable::index(int a, bool on) {
  const StatePath& path = paths_[a];
  const StateGraph& g = space_.graph(a);
  // The steps during which a sweeps a cell, one span per stretch of consecutive steps. Removal
  // collects the cells whose spans name a (each once) and clears them afterwards.
  std::vector<int> touched;
  newQuery();
  auto span = [&](int cell, int t, int last) {
    if (!on) {
      if (cell_stamp_[cell] != query_) {
        cell_stamp_[cell] = query_;
        touched.push_back(cell);
      }
      return;
    }
    std::vector<Span>& spans = cell_spans_[cell];
    staleSteps(cell);
    if (step_slot_[cell] == kNoSpans) step_slot_[cell] = kNoSlot;
    if (last == kNever) countEnd(cell, a, 1);
    if (!spans.empty() && spans.back().agent == a && spans.back().last == t - 1) {
      spans.back().last = last;
    } else {
      spans.push_back({t, last, a});
    }
    cell_blocks_[cell] |= blocksOf(t, last);
  };
  const int steps = static_cast<int>(path.size()) - 1;
  for (int t = 0; t < steps;) {
    const GridPose p = g.pose(path[t]);
    const Action act = stepAction(g, path[t], path[t + 1]);
    // A run of waits covers the body over all its steps: one span per cell.
    int last = t;
    if (act == Action::Wait) {
      while (last + 1 < steps && path[last + 2] == path[t]) ++last;
    }
    const CellSet& swept = space_.cells(a).swept(p.heading, act);
    forEachMapCell(swept, {p.x, p.y}, width_, height_, [&](int cell) { span(cell, t, last); });
    t = last + 1;
  }
  const GridPose end = g.pose(path.back());
  const CellSet& body = space_.cells(a).body(end.heading);
  forEachMapCell(body, {end.x, end.y}, width_, height_, [&](int cell) { span(cell, steps, kNever); });
  for (int cell : touched) {
    staleSteps(cell);
    std::vector<Span>& spans = cell_spans_[cell];
    for (const Span& r : spans) {
      if (r.agent == a && r.last == kNever) countEnd(cell, a, -1);
    }
    spans.erase(std::remove_if(spans.begin(), spans.end(), [a](const Span& r) { return r.agent == a; }),
                spans.end());
    if (spans.empty() && step_slot_[cell] == kNoSlot) step_slot_[cell] = kNoSpans;
    std::uint64_t blocks = 0;
    for (const Span& r : spans) blocks |= blocksOf(r.first, r.last);
    cell_blocks_[cell] = blocks;
  }
}

void SoftPathTable::insert(int a, const StatePath& path) {
  if (cell_spans_.empty()) {
    cell_spans_.resize(static_cast<std::size_t>(width_) * height_);
    cell_blocks_.assign(cell_spans_.size(), 0);
    cell_stamp_.assign(cell_spans_.size(), 0);
    end_cells_.assign(cell_spans_.size(), 0);
    end_agents_.assign(cell_spans_.size(), 0);
    step_slot_.assign(cell_spans_.size(), kNoSpans);
    end_squares_x_ = (width_ + kEndSide - 1) / kEndSide;
    end_squares_.assign(static_cast<std::size_t>(end_squares_x_) * ((height_ + kEndSide - 1) / kEndSide), 0);
  }
  paths_[a] = path;
  index(a, true);
  last_move_ = std::max(last_move_, static_cast<int>(path.size()) - 2);
}

void SoftPathTable::remove(int a) {
  index(a, false);
  const bool was_last = static_cast<int>(paths_[a].size()) - 2 == last_move_;
  paths_[a].clear();
  if (was_last) {
    last_move_ = -1;
    for (const StatePath& q : paths_) last_move_ = std::max(last_move_, static_cast<int>(q.size()) - 2);
  }
}

void SoftPathTable::newQuery() const {
  if (++query_ == 0) {  // wrapped: forget every stamp
    std::fill(stamp_.begin(), stamp_.end(), 0);
    std::fill(cell_stamp_.begin(), cell_stamp_.end(), 0);
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

void SoftPathTable::countEnd(int cell, int agent, int delta) {
  end_cells_[cell] = static_cast<std::uint16_t>(end_cells_[cell] + delta);
  end_agents_[cell] += delta * agent;
  const int square = (cell / width_) / kEndSide * end_squares_x_ + (cell % width_) / kEndSide;
  end_squares_[square] = static_cast<std::uint16_t>(end_squares_[square] + delta);
}

void SoftPathTable::collisionsAtEnd(int a, StateId s, Action action, std::vector<int>& out) const {
  const GridPose p = space_.graph(a).pose(s);
  collisionsAtEnd(a, space_.probe(a, p.heading, action), {p.x, p.y}, out);
}

void SoftPathTable::collisionsAtEnd(int a, const CellSet& probe, Cell p, std::vector<int>& out) const {
  if (cell_spans_.empty() || probe.empty()) return;
  const int x0 = std::max(p.x + probe.minX(), 0) / kEndSide, x1 = std::min(p.x + probe.maxX(), width_ - 1) / kEndSide;
  const int y0 = std::max(p.y + probe.minY(), 0) / kEndSide, y1 = std::min(p.y + probe.maxY(), height_ - 1) / kEndSide;
  bool any = false;
  for (int y = y0; y <= y1 && !any; ++y) {
    for (int x = x0; x <= x1 && !any; ++x) any = end_squares_[static_cast<std::size_t>(y) * end_squares_x_ + x] > 0;
  }
  if (!any) return;
  newQuery();
  stamp_[a] = query_;
  forEachMapCell(probe, {p.x, p.y}, width_, height_, [&](int cell) {
    if (end_cells_[cell] == 0) return;
    if (end_cells_[cell] == 1) {  // one agent stands there: end_agents_ names it
      if (firstVisit(end_agents_[cell])) out.push_back(end_agents_[cell]);
      return;
    }
    for (const Span& r : cell_spans_[cell]) {
      if (r.last == kNever && firstVisit(r.agent)) out.push_back(r.agent);
    }
  });
}

void SoftPathTable::collisionsHolding(int a, StateId s, int t, std::vector<int>& out) const {
  if (cell_spans_.empty()) return;
  newQuery();
  stamp_[a] = query_;
  const GridPose p = space_.graph(a).pose(s);
  // An agent that sweeps a cell of a's body during some step t or later (a span that ends at t
  // or later) covers a cell of the body's probe then.
  forEachMapCell(space_.probe(a, p.heading, Action::Wait), {p.x, p.y}, width_, height_, [&](int cell) {
    for (const Span& r : cell_spans_[cell]) {
      if (r.last >= t && firstVisit(r.agent)) out.push_back(r.agent);
    }
  });
}

template <class F>
void SoftPathTable::forOtherSpans(int a, const CellSet& cells, Cell origin, int from, int& forever_from,
                                  F&& f) const {
  forEachMapCell(cells, origin, width_, height_, [&](int cell) {
    for (const Span& r : cell_spans_[cell]) {
      if (r.agent == a) continue;
      if (r.last == kNever) {
        forever_from = std::min(forever_from, r.first);
      } else if (r.last >= from) {
        f(r.agent, std::max(r.first, from), r.last);
      }
    }
  });
}

void SoftPathTable::spansAt(int a, const CellSet& cells, Cell origin, std::vector<std::pair<int, int>>& runs,
                            int& forever_from, int from) const {
  if (cell_spans_.empty()) return;
  forOtherSpans(a, cells, origin, from, forever_from,
                [&](int, int first, int last) { runs.emplace_back(first, last); });
}

void SoftPathTable::unsafeRuns(int a, StateId s, Action action,
                               std::vector<std::pair<int, int>>& runs, int& forever_from,
                               int from) const {
  runs.clear();
  forever_from = kNever;
  if (cell_spans_.empty()) return;
  newQuery();
  met_.clear();
  // Neighbouring cells mostly hold the same pass of an agent, give or take a step: the spans
  // of each agent are merged as they come, so the caller sorts one run per pass, not per cell.
  forOtherSpans(a, s, action, from, forever_from, [&](int agent, int first, int last) {
    std::vector<std::pair<int, int>>& mine = agent_runs_[agent];
    if (firstVisit(agent)) {
      mine.clear();
      met_.push_back(agent);
    }
    bool merged = false;
    for (auto& run : mine) {
      if (first <= run.second + 1 && run.first <= last + 1) {
        run = {std::min(run.first, first), std::max(run.second, last)};
        merged = true;
        break;
      }
    }
    if (!merged) mine.emplace_back(first, last);
  });
  for (int b : met_) runs.insert(runs.end(), agent_runs_[b].begin(), agent_runs_[b].end());
}

namespace {

// A record's head (SoftPathTable::stepsOf): first and last in word 1, forever and the stale
// flag in word 2.
std::uint64_t packPair(int low, std::uint32_t high) {
  return static_cast<std::uint32_t>(low) | (static_cast<std::uint64_t>(high) << 32);
}
int lowOf(std::uint64_t word) { return static_cast<int>(static_cast<std::uint32_t>(word)); }
int highOf(std::uint64_t word) { return static_cast<int>(static_cast<std::uint32_t>(word >> 32)); }

}  // namespace

const std::uint64_t* SoftPathTable::stepsOf(int cell) const {
  int& slot = step_slot_[cell];
  if (slot < 0) {
    slot = step_slots_++;
    step_records_.resize(recordAt(step_slots_), 0);
    step_records_[recordAt(slot) + 2] = packPair(kNever, 1);  // stale: built below
  }
  if (!(step_records_[recordAt(slot) + 2] >> 32)) return &step_records_[recordAt(slot)];
  int first = kNever, last = -1, forever = kNever;
  for (const Span& r : cell_spans_[cell]) {
    if (r.last == kNever) {
      forever = std::min(forever, r.first);
    } else {
      first = std::min(first, r.first);
      last = std::max(last, r.last);
    }
  }
  const int words = last < 0 ? 0 : last / 64 + 1;
  if (words > step_stride_) {  // every record widened, its words kept
    const int old_stride = step_stride_;
    const std::vector<std::uint64_t> old = std::move(step_records_);
    step_stride_ = words;
    step_records_.assign(recordAt(step_slots_), 0);
    for (int k = 0; k < step_slots_; ++k) {
      const std::size_t from = static_cast<std::size_t>(k) * (kHeadWords + old_stride);
      std::copy(old.begin() + static_cast<std::ptrdiff_t>(from),
                old.begin() + static_cast<std::ptrdiff_t>(from + kHeadWords + old_stride),
                step_records_.begin() + static_cast<std::ptrdiff_t>(recordAt(k)));
    }
  }
  std::uint64_t* record = &step_records_[recordAt(slot)];
  std::fill(record + kHeadWords, record + kHeadWords + step_stride_, 0);
  std::uint64_t used = 0;
  for (const Span& r : cell_spans_[cell]) {
    if (r.last == kNever) continue;
    markSteps(record + kHeadWords, r.first, r.last);
    used |= bitRange(r.first / 64, r.last / 64);
  }
  record[0] = used;
  record[1] = packPair(first, static_cast<std::uint32_t>(last));
  record[2] = packPair(forever, 0);
  return record;
}

void SoftPathTable::markUnsafe(int a, StateId s, Action action, std::uint64_t* steps, int& lo, int& hi,
                               int& forever_from, int from) const {
  if (cell_spans_.empty()) return;
  if (!contains(a) && lastMove() < 64 * 64) {
    // Nobody to leave out: each cell's steps as a bitset, built when first asked after the
    // cell's spans changed and read a word at a time, only the words that have steps
    // (neighbouring states' probes share most of their cells).
    const GridPose p = space_.graph(a).pose(s);
    const int first_word = from / 64;
    const std::uint64_t first_mask = ~std::uint64_t{0} << (from % 64);
    const std::uint64_t from_word_on = first_word >= 64 ? 0 : ~std::uint64_t{0} << first_word;
    forEachMapCell(space_.probe(a, p.heading, action), {p.x, p.y}, width_, height_, [&](int cell) {
      const int slot = step_slot_[cell];
      if (slot == kNoSpans) return;  // nobody sweeps it
      const std::uint64_t* c = slot >= 0 ? &step_records_[recordAt(slot)] : nullptr;
      if (c == nullptr || (c[2] >> 32)) c = stepsOf(cell);  // none yet, or stale
      const int first = lowOf(c[1]), last = highOf(c[1]);
      forever_from = std::min(forever_from, lowOf(c[2]));
      if (last < from) return;  // every step it is swept ends before the search's first
      const std::uint64_t* words = c + kHeadWords;
      std::uint64_t used = c[0] & from_word_on;
      while (used != 0) {
        const int w = __builtin_ctzll(used);
        used &= used - 1;
        steps[w] |= words[w] & (w == first_word ? first_mask : ~std::uint64_t{0});
      }
      lo = std::min(lo, std::max(first, from));
      hi = std::max(hi, last);
    });
    return;
  }
  // Repeats from neighbouring cells cost a few word operations each: no bookkeeping per agent.
  forOtherSpans(a, s, action, from, forever_from, [&](int, int first, int last) {
    lo = std::min(lo, first);
    hi = std::max(hi, last);
    markSteps(steps, first, last);
  });
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
