#include "stress_cases.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/io/instance_generator.h"
#include "fleet_planner/runtime/random.h"

namespace fleet_planner::cli {

namespace {

int between(Rng& rng, int lo, int hi) {
  return static_cast<int>(rng.uniformInt(lo, std::max(lo, hi)));
}

void block(std::vector<std::uint8_t>& cells, int width, int height, int x, int y) {
  if (x >= 0 && y >= 0 && x < width && y < height)
    cells[static_cast<std::size_t>(y) * width + x] = 1;
}

// Scattered single obstacles, each cell blocked with probability `density`.
void scatter(Rng& rng, std::vector<std::uint8_t>& cells, double density) {
  for (auto& c : cells) {
    if (rng.uniform01() < density) c = 1;
  }
}

GridMap randomMap(Rng& rng, int width, int height) {
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(width) * height, 0);
  // A fifth of the maps are empty; the others up to 30 % blocked.
  if (rng.uniformInt(0, 4) != 0) scatter(rng, cells, 0.3 * rng.uniform01());
  return GridMap(width, height, std::move(cells));
}

// Rooms of 5..10 cells separated by one-cell walls, each wall with a door 1..4 cells wide.
GridMap roomsMap(Rng& rng, int width, int height) {
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(width) * height, 0);
  const int room = between(rng, 5, 10);
  for (int wx = room; wx < width - 1; wx += room + 1) {
    for (int y0 = 0; y0 < height; y0 += room + 1) {
      const int y1 = std::min(height, y0 + room + 1);
      const int door = between(rng, 1, 4), at = between(rng, y0, y1 - door);
      for (int y = y0; y < y1; ++y) {
        if (y < at || y >= at + door) block(cells, width, height, wx, y);
      }
    }
  }
  for (int wy = room; wy < height - 1; wy += room + 1) {
    for (int x0 = 0; x0 < width; x0 += room + 1) {
      const int x1 = std::min(width, x0 + room + 1);
      const int door = between(rng, 1, 4), at = between(rng, x0, x1 - door);
      for (int x = x0; x < x1; ++x) {
        if (x < at || x >= at + door) block(cells, width, height, x, wy);
      }
    }
  }
  if (rng.uniformInt(0, 1) == 0) scatter(rng, cells, 0.05 * rng.uniform01());
  return GridMap(width, height, std::move(cells));
}

// Open space crossed by 1..3 full walls with 1..2 gaps each (bottlenecks), plus a few
// rectangular obstacles.
GridMap corridorsMap(Rng& rng, int width, int height) {
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(width) * height, 0);
  const int walls = between(rng, 1, 3);
  for (int w = 0; w < walls; ++w) {
    const bool vertical = rng.uniformInt(0, 1) == 0;
    const int length = vertical ? height : width;
    const int at = between(rng, 2, (vertical ? width : height) - 3);
    std::vector<char> open(length, 0);
    for (int g = between(rng, 1, 2); g > 0; --g) {
      const int gap = between(rng, 1, 4), from = between(rng, 0, length - gap);
      for (int i = from; i < from + gap; ++i) open[i] = 1;
    }
    for (int i = 0; i < length; ++i) {
      if (!open[i]) block(cells, width, height, vertical ? at : i, vertical ? i : at);
    }
  }
  for (int r = between(rng, 0, 4); r > 0; --r) {
    const int w = between(rng, 1, 4), h = between(rng, 1, 4);
    const int x0 = between(rng, 0, width - w), y0 = between(rng, 0, height - h);
    for (int y = y0; y < y0 + h; ++y) {
      for (int x = x0; x < x0 + w; ++x) block(cells, width, height, x, y);
    }
  }
  return GridMap(width, height, std::move(cells));
}

// A window of a larger map with at least a third of its cells free (the best of a few draws).
GridMap cropMap(Rng& rng, const GridMap& source, int width, int height) {
  width = std::min(width, source.width());
  height = std::min(height, source.height());
  std::vector<std::uint8_t> best;
  int best_free = -1;
  for (int draw = 0; draw < 8 && best_free * 3 < width * height; ++draw) {
    const int x0 = between(rng, 0, source.width() - width),
              y0 = between(rng, 0, source.height() - height);
    std::vector<std::uint8_t> cells(static_cast<std::size_t>(width) * height);
    int free = 0;
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        cells[static_cast<std::size_t>(y) * width + x] = source.blocked(x0 + x, y0 + y) ? 1 : 0;
        free += source.blocked(x0 + x, y0 + y) ? 0 : 1;
      }
    }
    if (free > best_free) best_free = free, best = std::move(cells);
  }
  return GridMap(width, height, std::move(best));
}

double tenths(double v) { return std::floor(v * 10 + 1e-9) / 10; }

}  // namespace

std::uint64_t stressCaseSeed(std::uint64_t seed, int index) {
  Rng base(seed);
  Rng mixed(base.next() + static_cast<std::uint64_t>(index));
  return mixed.next();
}

StressCase makeStressCase(const StressCaseOptions& options, int index) {
  StressCase c;
  c.index = index;
  c.seed = stressCaseSeed(options.seed, index);
  Rng rng(c.seed);
  c.model.allow_backward = rng.uniformInt(0, 7) == 0;
  for (int map_try = 0; map_try < 8; ++map_try) {
    const int width = between(rng, options.min_side, options.max_side);
    const int height = between(rng, options.min_side, options.max_side);
    const int kinds = options.crop_maps.empty() ? 3 : 4;
    switch (rng.uniformInt(0, kinds - 1)) {
      case 0:
        c.map_kind = "random";
        c.map = randomMap(rng, width, height);
        break;
      case 1:
        c.map_kind = "rooms";
        c.map = roomsMap(rng, width, height);
        break;
      case 2:
        c.map_kind = "corridors";
        c.map = corridorsMap(rng, width, height);
        break;
      default: {
        const GridMap& source = options.crop_maps[rng.uniformInt(
            0, static_cast<std::int64_t>(options.crop_maps.size()) - 1)];
        c.map_kind = "crop:" + std::filesystem::path(source.source()).filename().string();
        c.map = cropMap(rng, source, width, height);
      }
    }
    c.map.setSource("stress instance " + std::to_string(index) + " (" + c.map_kind + ")");
    // Robots up to a sixth of the map's smaller side in radius / half-extent (at most 2 cells),
    // smaller and fewer on each failed placement.
    const int robots = between(rng, options.min_robots, options.max_robots);
    const double largest = tenths(std::min(2.0, std::min(c.map.width(), c.map.height()) / 6.0));
    double max_size = tenths(0.5 + rng.uniform01() * std::max(0.0, largest - 0.5));
    const double polygon_share = 0.5;
    for (int place_try = 0; place_try < 6; ++place_try) {
      GeneratorOptions g;
      g.robots = std::max(options.min_robots, robots - place_try / 2);
      g.seed = rng.next();
      g.model = c.model;
      g.attempts_per_robot = 300;
      g.max_size = std::max(0.5, max_size);
      g.min_radius = std::min(g.min_radius, g.max_size);
      g.polygon_share = polygon_share;
      try {
        c.instance = generateInstance(c.map, g);
        return c;
      } catch (const InvalidInput&) {
        ++c.generator_retries;
        max_size = tenths(max_size * 0.8);
      }
    }
  }
  throw InvalidInput("stress instance " + std::to_string(index) +
                     ": no robots could be placed on 8 maps");
}

std::string movingAiText(const GridMap& map) {
  std::string out = "type octile\nheight " + std::to_string(map.height()) + "\nwidth " +
                    std::to_string(map.width()) + "\nmap\n";
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) out += map.blocked(x, y) ? '@' : '.';
    out += '\n';
  }
  return out;
}

}  // namespace fleet_planner::cli
