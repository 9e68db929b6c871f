// Fuzz target: the benchmark instance reader, parseBenchmarkInstance (instance_io.h), on
// arbitrary bytes.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "fleet_planner/io/instance_io.h"
#include "fuzz_outcome.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fleet_planner;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  fuzz::parsesOrRejects("fuzz.txt", [&] {
    const Instance instance = parseBenchmarkInstance(in, "fuzz.txt");
    fuzz::check(!instance.robots.empty(), "instance without robots accepted");
    for (const Robot& robot : instance.robots) {
      fuzz::check(footprintProblem(robot.footprint).empty(), "bad footprint accepted");
      fuzz::check(validHeading(robot.start.heading) && validHeading(robot.target.heading),
                  "bad heading accepted");
    }
  });
  return 0;
}
