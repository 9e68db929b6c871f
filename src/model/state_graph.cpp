#include "fleet_planner/model/state_graph.h"

namespace fleet_planner {

StateGraph::StateGraph(const GridMap& map, const ObstacleIndex& obstacles,
                       std::shared_ptr<const FootprintCells> cells, ActionModel model)
    : width_(map.width()), height_(map.height()), cells_(std::move(cells)), model_(model) {
  int log2_width = 0;
  while ((std::int64_t{1} << log2_width) < width_) ++log2_width;
  row_shift_ = 29 + log2_width;
  const std::uint64_t w = static_cast<std::uint64_t>(std::max(width_, 1));
  row_magic_ = ((std::uint64_t{1} << row_shift_) + w - 1) / w;
  flags_.assign(static_cast<std::size_t>(map.numCells()) * kHeadings, 0);
  const FootprintCells& fc = *cells_;
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      for (int h = 0; h < kHeadings; ++h) {
        if (!obstacles.blocked(fc.body(h), {x, y})) flags_[id({x, y, h})] = 1;
      }
    }
  }
  for (StateId s = 0; s < stateIdCount(); ++s) {
    if (!(flags_[s] & 1u)) continue;
    ++num_valid_;
    const GridPose p = pose(s);
    // A move sweeps the footprints at every cell on the way and nothing else, so it is free when
    // the states on the way are valid (their headings are the same).
    const Cell dir = kHeadingStep[p.heading];
    auto clear = [&](int sign) {
      for (int k = 1; k <= model_.step; ++k) {
        if (!valid(id({p.x + sign * k * dir.x, p.y + sign * k * dir.y, p.heading}))) return false;
      }
      return true;
    };
    if (clear(1)) flags_[s] |= 1u << static_cast<int>(Action::Forward);
    if (model_.allow_backward && clear(-1)) flags_[s] |= 1u << static_cast<int>(Action::Backward);
    for (Action a : {Action::RotateCcw, Action::RotateCw}) {
      if (valid(next(s, a)) && !obstacles.blocked(fc.swept(p.heading, a), {p.x, p.y})) {
        flags_[s] |= 1u << static_cast<int>(a);
      }
    }
    for (int a = 1; a < kActions; ++a) num_edges_ += (flags_[s] >> a) & 1u;
  }
}

}  // namespace fleet_planner
