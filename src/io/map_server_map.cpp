#include "map_server_map.h"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <istream>
#include <string>
#include <vector>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/io/map_io.h"
#include "io_helpers.h"
#include "pgm_image.h"

namespace fleet_planner {

namespace io {

namespace {

using Mode = MapServerMode;

double threshold(const io::YamlMapping& fields, const std::string& key, double fallback) {
  const io::YamlField* field = fields.find(key);
  if (field == nullptr) return fallback;
  const double value = fields.number(*field, key);
  if (value < 0.0 || value > 1.0) {
    throw ParseError(fields.file(), field->line,
                     key + " must be in [0, 1], got " + io::formatNumber(value));
  }
  return value;
}

}  // namespace

MapServerYaml parseMapServerYaml(std::istream& in, const std::string& yaml_path) {
  const YAML::Node root = io::parseYaml(in, yaml_path);
  const io::YamlMapping fields(
      root, yaml_path, 0, "the map file",
      {"image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh", "mode"});
  MapServerYaml yaml;

  const io::YamlField& image = fields.require("image");
  yaml.image = io::resolveRelativeTo(yaml_path, fields.string(image, "image"));
  yaml.image_line = image.line;

  const io::YamlField& resolution = fields.require("resolution");
  yaml.resolution = fields.number(resolution, "resolution");
  if (!(yaml.resolution > 0.0)) {
    throw ParseError(yaml_path, resolution.line,
                     "resolution must be positive, got " + io::formatNumber(yaml.resolution));
  }

  const io::YamlField& origin = fields.require("origin");
  if (!origin.node.IsSequence() || origin.node.size() != 3) {
    throw ParseError(yaml_path, origin.line, "origin must be a list [x, y, yaw]");
  }
  const char* const names[3] = {"origin x", "origin y", "origin yaw"};
  double values[3];
  for (std::size_t i = 0; i < 3; ++i) {
    const YAML::Node element = origin.node[i];
    values[i] = io::yamlNumber(element, yaml_path, io::yamlLine(element, origin.line), names[i]);
  }
  yaml.origin = MapOrigin{values[0], values[1], values[2]};

  if (const io::YamlField* negate = fields.find("negate")) {
    const std::string text = negate->node.IsScalar() ? negate->node.Scalar() : "";
    if (text == "0" || text == "false") {
      yaml.negate = false;
    } else if (text == "1" || text == "true") {
      yaml.negate = true;
    } else {
      throw ParseError(yaml_path, negate->line, "negate must be 0 or 1");
    }
  }

  yaml.occupied_thresh = threshold(fields, "occupied_thresh", yaml.occupied_thresh);
  yaml.free_thresh = threshold(fields, "free_thresh", yaml.free_thresh);
  if (yaml.free_thresh >= yaml.occupied_thresh) {
    const io::YamlField* blame = fields.find("free_thresh");
    if (blame == nullptr) blame = fields.find("occupied_thresh");
    throw ParseError(yaml_path, blame != nullptr ? blame->line : 0,
                     "free_thresh (" + io::formatNumber(yaml.free_thresh) +
                         ") must be below occupied_thresh (" +
                         io::formatNumber(yaml.occupied_thresh) + ")");
  }

  if (const io::YamlField* mode = fields.find("mode")) {
    const std::string text = mode->node.IsScalar() ? mode->node.Scalar() : "";
    if (text == "trinary") {
      yaml.mode = Mode::Trinary;
    } else if (text == "scale") {
      yaml.mode = Mode::Scale;
    } else if (text == "raw") {
      yaml.mode = Mode::Raw;
    } else {
      throw ParseError(yaml_path, mode->line,
                       "mode must be trinary, scale or raw, got " + io::quoted(text));
    }
  }
  return yaml;
}

namespace {

/// 1 blocked, 0 free, -1 unknown, for one pixel (see loadMapServerMap in map_io.h).
int occupancy(const MapServerYaml& yaml, unsigned value, unsigned maxval) {
  double p = 0.0;
  if (yaml.mode == Mode::Raw) {
    const unsigned shade = yaml.negate ? maxval - value : value;
    const double percent = std::round(shade * 255.0 / maxval);
    if (percent > 100.0) return -1;
    p = percent / 100.0;
  } else {
    p = yaml.negate ? static_cast<double>(value) / maxval
                    : static_cast<double>(maxval - value) / maxval;
  }
  if (p > yaml.occupied_thresh) return 1;
  if (p < yaml.free_thresh) return 0;
  return -1;
}

}  // namespace

GridMap mapServerGrid(const MapServerYaml& yaml, const PgmImage& image,
                      const MapServerOptions& options, const std::string& source) {
  const int width = image.width;
  const int height = image.height;
  std::vector<std::uint8_t> blocked(static_cast<std::size_t>(width) * height, 0);
  for (int row = 0; row < height; ++row) {
    const int y = height - 1 - row;
    for (int x = 0; x < width; ++x) {
      const unsigned value = image.pixels[static_cast<std::size_t>(row) * width + x];
      const int occ = occupancy(yaml, value, static_cast<unsigned>(image.maxval));
      const bool is_blocked = occ == 1 || (occ == -1 && !options.unknown_is_free);
      blocked[static_cast<std::size_t>(y) * width + x] = is_blocked ? 1 : 0;
    }
  }
  GridMap map(width, height, std::move(blocked), yaml.resolution, yaml.origin);
  map.setSource(source);
  return map;
}

}  // namespace io

GridMap loadMapServerMap(const std::string& yaml_path, const MapServerOptions& options) {
  std::ifstream in(yaml_path, std::ios::binary);
  if (!in) throw ParseError(yaml_path, 0, "cannot open file");
  const io::MapServerYaml yaml = io::parseMapServerYaml(in, yaml_path);
  if (!std::ifstream(yaml.image, std::ios::binary)) {
    throw ParseError(yaml_path, yaml.image_line, "cannot open image file '" + yaml.image + "'");
  }
  return io::mapServerGrid(yaml, io::readPgm(yaml.image, &options.limits), options, yaml_path);
}

bool isMapServerMapPath(const std::string& path) { return io::hasYamlExtension(path); }

GridMap loadMap(const std::string& path, const MapServerOptions& options) {
  if (isMapServerMapPath(path)) return loadMapServerMap(path, options);
  return loadMovingAiMap(path, options.limits);
}

}  // namespace fleet_planner
