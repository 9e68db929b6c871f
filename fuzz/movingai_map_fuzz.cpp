// Fuzz target: the MovingAI map reader, parseMovingAiMap (map_io.h), on arbitrary bytes.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "fleet_planner/io/map_io.h"
#include "fuzz_outcome.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fleet_planner;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  fuzz::parsesOrRejects("fuzz.map", [&] {
    const GridMap map = parseMovingAiMap(in, "fuzz.map");
    fuzz::check(map.width() >= 1 && map.height() >= 1, "empty map accepted");
    fuzz::check(map.cells().size() == static_cast<std::size_t>(map.width()) * map.height(),
                "cell count is not width x height");
    // A map holds at least one byte of input per cell.
    fuzz::check(map.cells().size() <= size, "more cells than input bytes");
  });
  return 0;
}
