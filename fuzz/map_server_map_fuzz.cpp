// Fuzz target: the ROS map_server map reader (loadMapServerMap in map_io.h) without files.
// The input is the YAML text, a NUL byte, then the PGM image's bytes (no NUL: all YAML, no
// image). Both halves are parsed on their own, so each reader is fuzzed even when the other
// half is bad; when both parse, the grid is built from them as loadMapServerMap does.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "fleet_planner/io/map_io.h"
#include "fuzz_outcome.h"
#include "map_server_map.h"
#include "pgm_image.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fleet_planner;
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t nul = input.find('\0');
  std::istringstream yaml_text(input.substr(0, nul));
  const std::string pgm = nul == std::string::npos ? std::string() : input.substr(nul + 1);

  io::MapServerYaml yaml;
  const bool yaml_ok = fuzz::parsesOrRejects("fuzz/map.yaml", [&] {
    yaml = io::parseMapServerYaml(yaml_text, "fuzz/map.yaml");
    fuzz::check(yaml.resolution > 0.0, "non-positive resolution accepted");
    fuzz::check(yaml.free_thresh < yaml.occupied_thresh, "free_thresh >= occupied_thresh accepted");
  });
  io::PgmImage image;
  const bool image_ok = fuzz::parsesOrRejects("fuzz/map.pgm", [&] {
    image = io::parsePgm(pgm, "fuzz/map.pgm");
    fuzz::check(image.pixels.size() == static_cast<std::size_t>(image.width) * image.height,
                "pixel count is not width x height");
    // Every pixel takes at least one byte of the image.
    fuzz::check(image.pixels.size() <= pgm.size(), "more pixels than image bytes");
  });
  if (!yaml_ok || !image_ok) return 0;

  for (const bool unknown_is_free : {false, true}) {
    MapServerOptions options;
    options.unknown_is_free = unknown_is_free;
    const GridMap map = io::mapServerGrid(yaml, image, options, "fuzz/map.yaml");
    fuzz::check(map.width() == image.width && map.height() == image.height,
                "grid size differs from the image size");
  }
  return 0;
}
