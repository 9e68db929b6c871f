#pragma once
/// Internal: a minimal reader for PGM (netpbm graymap) images, P2 and P5, as used by ROS
/// map_server maps. Not part of the public API.
#include <cstdint>
#include <string>
#include <vector>

#include "fleet_planner/runtime/resource_limits.h"

namespace fleet_planner::io {

struct PgmImage {
  int width = 0;
  int height = 0;
  int maxval = 0;
  std::vector<std::uint16_t> pixels;  ///< row-major, row 0 = top row of the image
};

/// Parses the bytes of a P2 (plain) or P5 (binary) PGM image with maxval 1..65535 and `#`
/// comments in the header (and, in P2, between pixel values); `path` names it in messages.
/// Throws ParseError(path, line, reason): "only PGM images are supported" for any other file
/// type, and for a bad header, a pixel above maxval, or truncated or extra data. The line is 0
/// for binary pixel data, for truncation and for the file as a whole. With `limits`, throws
/// ResourceLimitError for an image of more than limits->max_map_cells pixels before allocating.
PgmImage parsePgm(const std::string& data, const std::string& path, const ResourceLimits* limits = nullptr);

/// Reads a PGM file (see parsePgm); a file that cannot be opened throws ParseError(path, 0, ...).
PgmImage readPgm(const std::string& path, const ResourceLimits* limits = nullptr);

}  // namespace fleet_planner::io
