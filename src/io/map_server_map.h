#pragma once
/// Internal: the two steps of loadMapServerMap (map_io.h) on text already in memory, so that
/// the reader can be tested and fuzzed without files. Not part of the public API.
#include <iosfwd>
#include <string>

#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/io/map_io.h"
#include "pgm_image.h"

namespace fleet_planner::io {

enum class MapServerMode { Trinary, Scale, Raw };

/// The keys of a map_server YAML file (see loadMapServerMap), checked.
struct MapServerYaml {
  std::string image;  ///< resolved against the YAML's folder
  int image_line = 0;
  double resolution = 0.0;
  MapOrigin origin;
  bool negate = false;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  MapServerMode mode = MapServerMode::Trinary;
};

/// Parses the YAML text of a map_server map from `in`. `yaml_path` names it in messages and is
/// the file whose folder a relative `image` is resolved against. Throws ParseError(yaml_path,
/// line, reason) as loadMapServerMap documents; does not open the image.
MapServerYaml parseMapServerYaml(std::istream& in, const std::string& yaml_path);

/// The grid of `image` read with the settings of `yaml` (see loadMapServerMap); source() =
/// `source`.
GridMap mapServerGrid(const MapServerYaml& yaml, const PgmImage& image,
                      const MapServerOptions& options, const std::string& source);

}  // namespace fleet_planner::io
