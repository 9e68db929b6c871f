#include "fleet_planner/solvers/lacam/la_pibt.h"

#include <algorithm>
#include <memory>

#include "fleet_planner/model/collision.h"
#include "fleet_planner/solvers/search/space_time_astar.h"

namespace fleet_planner {

namespace {

// Stable sort of the first n (at most kActions) entries of `items`.
template <class Array, class Less>
void sortFew(Array& items, int n, Less less) {
  for (int i = 1; i < n; ++i) {
    for (int j = i; j > 0 && less(items[j], items[j - 1]); --j) std::swap(items[j], items[j - 1]);
  }
}

// The cells of `set` placed at `at` that `other` placed at `other_at` does not cover.
CellSet outside(const CellSet& set, Cell at, const CellSet& other, Cell other_at) {
  std::vector<Cell> cells;
  for (const Cell& c : set.cells()) {
    const Cell p{c.x + at.x, c.y + at.y};
    if (!other.contains(p.x - other_at.x, p.y - other_at.y)) cells.push_back(p);
  }
  return CellSet::fromCells(std::move(cells));
}

}  // namespace

LaPibt::LaPibt(const SearchSpace& space, std::uint64_t seed, bool remember_escapes)
    : space_(space),
      rng_(seed),
      seen_agent_(space.numAgents(), 0),
      candidates_at_(space.numAgents(), kNoState),
      candidates_(space.numAgents()),
      candidate_distances_(space.numAgents()),
      assigned_(space.numAgents(), 0),
      remember_escapes_(remember_escapes) {
  if (space.numAgents() == 0) return;
  width_ = space.graph(0).width();
  height_ = space.graph(0).height();
  const ActionModel model = space.graph(0).actionModel();
  for (int h = 0; h < kHeadings; ++h) {
    for (int act = 0; act < kActions; ++act) {
      step_to_[h][act] = applyAction({0, 0, h}, static_cast<Action>(act), model);
    }
  }
  // Per footprint (agents with the same cells share them), heading and action: the cells
  // fits() reads, the contact probe of the sweep (it meets every body or sweep that the sweep
  // meets) without the mover's own footprint, which no other claim covers; and the cells of
  // its BodyStep.
  using Tables = std::pair<std::shared_ptr<const Ahead>, std::shared_ptr<const BodySteps>>;
  std::unordered_map<const FootprintCells*, Tables> made;
  ahead_.resize(space.numAgents());
  body_steps_.resize(space.numAgents());
  for (int a = 0; a < space.numAgents(); ++a) {
    auto& [sets, steps] = made[&space.cells(a)];
    if (!sets) {
      auto ahead = std::make_shared<Ahead>();
      auto body_steps = std::make_shared<BodySteps>();
      for (int h = 0; h < kHeadings; ++h) {
        const CellSet& before = space.cells(a).body(h);
        for (int act = 0; act < kActions; ++act) {
          const Action action = static_cast<Action>(act);
          (*ahead)[h][act] = outside(space.probe(a, h, action), {0, 0}, before, {0, 0});
          const GridPose q = step_to_[h][act];
          const CellSet& after = space.cells(a).body(q.heading);
          (*body_steps)[h][act] = {outside(before, {0, 0}, after, {q.x, q.y}),
                                   outside(after, {q.x, q.y}, before, {0, 0}),
                                   outside(space.cells(a).swept(h, action), {0, 0}, before, {0, 0})};
        }
      }
      sets = std::move(ahead);
      steps = std::move(body_steps);
    }
    ahead_[a] = sets;
    body_steps_[a] = steps;
  }
  owner_.assign(static_cast<std::size_t>(width_) * height_, -1);
  placed_.assign(space.numAgents(), kNoState);
  at_.resize(space.numAgents());
}

void LaPibt::claim(int a, const CellSet& set, const GridPose& p) {
  forEachMapCell(set, {p.x, p.y}, width_, height_, [&](std::size_t cell) {
    owner_[cell] = a;
    swept_.push_back(cell);
  });
}

void LaPibt::claimMotion(int a, Action action) {
  const GridPose& p = at_[a];
  // The footprint's own cells name a already, and no other claim takes them this step: a
  // motion's claim is its sweep.
  claim(a, (*body_steps_[a])[p.heading][static_cast<int>(action)].sweeps, p);
}

void LaPibt::claimFootprints(const Config& current) {
  for (const std::size_t cell : swept_) owner_[cell] = -1;
  swept_.clear();
  // Consecutive configurations differ in a few agents: only their footprints are moved. A cell
  // is cleared only if it still names the agent (another may have stepped there already).
  for (int b = 0; b < space_.numAgents(); ++b) {
    if (placed_[b] == current[b]) continue;
    const StateGraph& g = space_.graph(b);
    const GridPose q = g.pose(current[b]);
    if (placed_[b] != kNoState) {
      const GridPose old = g.pose(placed_[b]);
      const int act = oneStep(old, q);
      if (act > 0) {  // one step on: only the cells that change
        const BodyStep& changed = (*body_steps_[b])[old.heading][act];
        forEachMapCell(changed.leaves, {old.x, old.y}, width_, height_, [&](std::size_t cell) {
          if (owner_[cell] == b) owner_[cell] = -1;
        });
        forEachMapCell(changed.enters, {old.x, old.y}, width_, height_,
                       [&](std::size_t cell) { owner_[cell] = b; });
        placed_[b] = current[b];
        at_[b] = q;
        continue;
      }
      forEachMapCell(space_.cells(b).body(old.heading), {old.x, old.y}, width_, height_,
                     [&](std::size_t cell) {
                       if (owner_[cell] == b) owner_[cell] = -1;
                     });
    }
    forEachMapCell(space_.cells(b).body(q.heading), {q.x, q.y}, width_, height_,
                   [&](std::size_t cell) { owner_[cell] = b; });
    placed_[b] = current[b];
    at_[b] = q;
  }
}

int LaPibt::oneStep(const GridPose& from, const GridPose& to) const {
  const GridPose d{to.x - from.x, to.y - from.y, to.heading};
  for (int act = 1; act < kActions; ++act) {
    if (step_to_[from.heading][act] == d) return act;
  }
  return -1;
}

const StateChoices& LaPibt::candidates(int a, StateId s) {
  StateChoices& out = candidates_[a];
  if (candidates_at_[a] == s) return out;
  std::array<int, kActions>& distance = candidate_distances_[a];
  out = StateChoices{};
  distance[0] = space_.distance(a, s);
  out.push(s, Action::Wait);
  space_.graph(a).forEachSuccessor(s, [&](Action action, StateId next) {
    const int d = space_.distance(a, next);
    if (d < 0 || !space_.allows(a, s, action)) return;
    distance[out.size()] = d;
    out.push(next, action);
  });
  candidates_at_[a] = s;
  return out;
}

bool LaPibt::fits(int a, Action action, std::vector<int>* in_way) const {
  const GridPose p = at_[a];
  if (++agent_query_ == 0) {  // wrapped: forget every stamp
    std::fill(seen_agent_.begin(), seen_agent_.end(), 0);
    agent_query_ = 1;
  }
  const std::size_t first_in_way = in_way != nullptr ? in_way->size() : 0;
  bool clear = true;
  // Locals, so that the loop does not reload them after every push onto in_way.
  const std::int32_t* owner = owner_.data();
  forEachMapCell((*ahead_[a])[p.heading][static_cast<int>(action)], {p.x, p.y}, width_, height_,
                 [&](std::size_t cell) {
                   const int b = owner[cell];
                   if (b < 0 || b == a) return true;
                   clear = false;
                   if (in_way == nullptr) return false;  // one is enough
                   if (!assigned_[b] && seen_agent_[b] != agent_query_) {
                     seen_agent_[b] = agent_query_;
                     in_way->push_back(b);
                   }
                   return true;
                 });
  // Agent order, whatever the cells' order.
  if (in_way != nullptr) std::sort(in_way->begin() + static_cast<std::ptrdiff_t>(first_in_way), in_way->end());
  return clear;
}

StateChoices LaPibt::escapeSteps(int a, StateId from, const CellSet& sweep, Cell origin) const {
  // Breadth-first from `from` in a's own graph (other agents ignored), remembering each state's
  // first step; the depth at which a first step first reaches a state clear of the sweep ranks it.
  const StateGraph& g = space_.graph(a);
  auto clear = [&](StateId s) {
    const GridPose p = g.pose(s);
    return !CellSet::overlap(space_.cells(a).body(p.heading), {p.x, p.y}, sweep, origin);
  };
  // Seen states carry this search's stamp (a fresh one per search; all cleared on wrap-around).
  if (seen_.size() < static_cast<std::size_t>(g.stateIdCount())) seen_.resize(g.stateIdCount(), 0);
  if (++seen_query_ == 0) {
    std::fill(seen_.begin(), seen_.end(), 0);
    seen_query_ = 1;
  }
  auto firstSeen = [&](StateId s) {
    if (seen_[s] == seen_query_) return false;
    seen_[s] = seen_query_;
    return true;
  };
  firstSeen(from);
  StateChoices firsts;
  std::array<int, kActions> depth_of_first{};
  std::vector<EscapeItem>& queue = escape_queue_;
  queue.clear();
  g.forEachSuccessor(from, [&](Action action, StateId next) {
    if (!space_.allows(a, from, action)) return;
    depth_of_first[firsts.size()] = -1;
    queue.push_back({next, firsts.size(), 1});
    firsts.push(next, action);
    firstSeen(next);
  });
  int found_depth = -1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const EscapeItem item = queue[head];
    if (found_depth >= 0 && item.depth > found_depth + 1) break;
    if (depth_of_first[item.first] < 0 && clear(item.s)) {
      depth_of_first[item.first] = item.depth;
      if (found_depth < 0) found_depth = item.depth;
    }
    if (item.depth >= kEscapeDepth || queue.size() >= kEscapeStates) continue;
    g.forEachSuccessor(item.s, [&](Action action, StateId next) {
      if (!space_.allows(a, item.s, action) || !firstSeen(next)) return;
      queue.push_back({next, item.first, item.depth + 1});
    });
  }
  std::array<int, kActions> order{};
  int found = 0;
  for (int k = 0; k < firsts.size(); ++k) {
    if (depth_of_first[k] >= 0) order[found++] = k;
  }
  sortFew(order, found, [&](int x, int y) { return depth_of_first[x] < depth_of_first[y]; });
  StateChoices result;
  for (int i = 0; i < found; ++i) result.push(firsts[order[i]], firsts.action(order[i]));
  return result;
}

StateChoices LaPibt::cachedEscape(int a, StateId from, int pusher, Action action) {
  // The escape depends on nothing but a's graph, the map and the pusher's sweep: the same
  // situations recur across configurations, so the answers are kept (up to a bound).
  const std::uint64_t agent_state = (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(from);
  const std::uint64_t pusher_motion = (static_cast<std::uint64_t>(pusher) << 35) |
                                      (static_cast<std::uint64_t>(action) << 32) |
                                      static_cast<std::uint32_t>(placed_[pusher]);
  Escape* slot = nullptr;
  if (remember_escapes_) {
    // Allocated at the first push, about 256 slots an agent: the many small searches (pair
    // proofs, a knot alone) pay little for it, and a large fleet's table stays in the nearer
    // caches, which pays for the few more escapes searched again.
    if (escapes_.empty()) {
      std::size_t slots = 1024;
      while (slots < kEscapeSlots && slots < 256 * static_cast<std::size_t>(space_.numAgents())) slots *= 2;
      escapes_.resize(slots);
    }
    const std::uint64_t hash = ((agent_state * 0x9e3779b97f4a7c15ULL) ^ pusher_motion) * 0xff51afd7ed558ccdULL;
    slot = &escapes_[(hash >> 40) & (escapes_.size() - 1)];
    if (slot->agent_state == agent_state && slot->pusher_motion == pusher_motion) return slot->steps;
  }
  const GridPose& p = at_[pusher];
  const StateChoices steps = escapeSteps(a, from, space_.cells(pusher).swept(p.heading, action), {p.x, p.y});
  if (slot != nullptr) *slot = {agent_state, pusher_motion, steps};
  return steps;
}

bool LaPibt::assign(int a, const Config& current, Config& next, int pusher, Action pushing) {
  assigned_[a] = 1;
  next[a] = current[a];
  // One candidate step: a moves there, or waits (for the agents in its way to clear it, or
  // because waiting is the best it can do), or tries its next candidate.
  enum class Outcome { Moves, Waits, Next };
  auto attempt = [&](StateId s, Action action) {
    if (action == Action::Wait) return Outcome::Waits;
    // The agents in a's way are appended to in_way_ after `mark`; pushes nested in this one
    // append after them and take theirs off again before they return.
    const std::size_t mark = in_way_.size();
    if (fits(a, action, &in_way_)) {
      in_way_.resize(mark);
      next[a] = s;
      claimMotion(a, action);
      return Outcome::Moves;
    }
    // Blocked: if only agents still to move are in the way, ask them to clear, and wait.
    const std::size_t end = in_way_.size();
    if (end == mark) return Outcome::Next;
    bool cleared = true;
    for (std::size_t k = mark; k < end; ++k) {
      const int b = in_way_[k];
      if (!assigned_[b]) cleared = assign(b, current, next, a, action) && cleared;
    }
    in_way_.resize(mark);
    return cleared ? Outcome::Waits : Outcome::Next;
  };
  if (pusher >= 0) {
    // Pushed: step towards the nearest state clear of the cells the pusher will sweep next
    // step. Large robots without reverse often need a turn first, so progress is enough.
    const StateChoices options = cachedEscape(a, current[a], pusher, pushing);
    for (int i = 0; i < options.size(); ++i) {
      const Outcome o = attempt(options[i], options.action(i));
      if (o == Outcome::Moves) return true;
      if (o == Outcome::Waits) return false;
    }
    return false;
  }
  // Best first by distance to the target; random tie-break from the seed.
  const StateChoices& all = candidates(a, current[a]);
  if (candidate_distances_[a][0] == 0) {
    // At its target: waiting ranks first whatever the draws (every other state is a step or
    // more away), so it waits, unsorted; its draws are still taken, so that the random
    // stream, and so the search, stay as they were.
    for (int i = 0; i < all.size(); ++i) rng_.next();
    return true;
  }
  struct Ranked {
    int distance;
    std::uint64_t tie;
    int index;
  };
  auto before = [](const Ranked& x, const Ranked& y) {
    return x.distance != y.distance ? x.distance < y.distance : x.tie < y.tie;
  };
  std::array<Ranked, kActions> ranked;
  int best = 0;
  for (int i = 0; i < all.size(); ++i) {
    ranked[i] = {candidate_distances_[a][i], rng_.next(), i};
    if (before(ranked[i], ranked[best])) best = i;
  }
  // Most agents take their best candidate (or wait): the others are ranked only when it is
  // blocked, in the order a stable sort of all of them would give after it.
  const Outcome first = attempt(all[best], all.action(best));
  if (first != Outcome::Next) return true;
  std::copy(ranked.begin() + best + 1, ranked.begin() + all.size(), ranked.begin() + best);
  const int rest = all.size() - 1;
  sortFew(ranked, rest, before);
  for (int i = 0; i < rest; ++i) {
    if (attempt(all[ranked[i].index], all.action(ranked[i].index)) != Outcome::Next) return true;
  }
  return true;
}

bool LaPibt::generate(const Config& current, const std::vector<std::pair<int, StateId>>& fixed,
                      const std::vector<int>& order, Config& next) {
  const int n = space_.numAgents();
  next.assign(n, kNoState);
  std::fill(assigned_.begin(), assigned_.end(), 0);
  claimFootprints(current);
  for (const auto& [a, s] : fixed) {
    const Action action = stepAction(space_.graph(a), current[a], s);
    if (assigned_[a] || !fits(a, action)) return false;
    next[a] = s;
    if (action != Action::Wait) claimMotion(a, action);
    assigned_[a] = 1;
  }
  for (int a : order) {
    if (!assigned_[a]) assign(a, current, next, -1, Action::Wait);
  }
  return true;
}

}  // namespace fleet_planner
