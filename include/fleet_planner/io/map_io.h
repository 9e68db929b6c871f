#pragma once
/// Reading maps into a GridMap: MovingAI benchmark maps (.map) and ROS map_server maps
/// (YAML + PGM). Bad input throws ParseError naming the file and line; nothing is fixed up.
#include <iosfwd>
#include <string>

#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/runtime/resource_limits.h"

namespace fleet_planner {

/// Parses a MovingAI map: the header lines `type <anything>`, `height H` and `width W` (height
/// and width in either order), `map`, then H rows of exactly W characters. `.` `G` `S` are
/// passable, `@` `O` `T` `W` blocked. A trailing '\r' on a line is ignored, and so are blank
/// lines after the last row. Cell (x, y) is column x of map row y (row 0 = first row after
/// `map`); resolution 1, origin (0, 0, 0). `source` names the input in messages and becomes
/// GridMap::source(). Throws ParseError(source, line, reason) for an unknown character (with
/// its 1-based column), a wrong row length, missing or extra rows, a missing or repeated
/// header line, or a size that is not an integer in [1, 100000] (or more than 2^28 cells).
/// Throws ResourceLimitError, before reading the rows, for a header of more than
/// limits.max_map_cells cells. Memory grows with the rows read, so a header claiming a large
/// map without its rows costs nothing but the error.
GridMap parseMovingAiMap(std::istream& in, const std::string& source, const ResourceLimits& limits = {});

/// Reads a MovingAI map file (see parseMovingAiMap); source() = `path`. Throws ParseError(path,
/// 0, ...) if the file cannot be opened.
GridMap loadMovingAiMap(const std::string& path, const ResourceLimits& limits = {});

/// How loadMapServerMap treats cells that are neither free nor occupied, and (for loadMap, both
/// formats) the largest map accepted.
struct MapServerOptions {
  bool unknown_is_free = false;  ///< false: unknown cells are blocked
  ResourceLimits limits;         ///< max_map_cells: checked on the header, before the grid is allocated
};

/// Reads a ROS map_server map: a YAML file with the keys
/// - `image` (required): the image, relative to the YAML file's folder or absolute; PGM only
///   (P2 or P5, maxval <= 65535, `#` comments in the header);
/// - `resolution` (required): metres per cell, > 0;
/// - `origin` (required): [x, y, yaw] of the lower-left corner of the map;
/// - `negate` (0 or 1, also true/false; default 0);
/// - `occupied_thresh` (default 0.65), `free_thresh` (default 0.196): in [0, 1], free < occupied;
/// - `mode`: `trinary` (default), `scale` or `raw`.
/// Other keys are rejected. Each pixel v gets an occupancy p, as map_server computes it:
/// - trinary and scale: p = (maxval - v) / maxval, or v / maxval with negate;
/// - raw: the pixel is a percentage r = round(v' * 255 / maxval) with v' = v, or maxval - v with
///   negate (for an 8-bit image r is the pixel value); r > 100 means unknown, else p = r / 100.
/// Then p > occupied_thresh is blocked, p < free_thresh is free and anything else is unknown
/// (scale mode's intermediate costs count as unknown, since the grid is binary). Unknown cells
/// are blocked unless options.unknown_is_free. Image row 0 is the top of the map: grid
/// y = height - 1 - image row, so grid y = 0 sits at the origin (as in nav_msgs/OccupancyGrid).
/// Throws ParseError naming the YAML file and the line of the offending key (missing keys,
/// non-numbers, NaN, bad thresholds or mode, missing image file), or naming the image file for
/// a bad image (a non-PGM image, a bad header, a value above maxval, truncated or extra data;
/// line 0 for binary data).
GridMap loadMapServerMap(const std::string& yaml_path, const MapServerOptions& options = {});

/// A path that loadMap reads as a map_server map: ending in `.yaml` or `.yml` (any case).
bool isMapServerMapPath(const std::string& path);

/// Reads either kind of map: a map_server map (isMapServerMapPath) with loadMapServerMap,
/// anything else with loadMovingAiMap.
GridMap loadMap(const std::string& path, const MapServerOptions& options = {});

}  // namespace fleet_planner
