// Fuzz target: the YAML scenario reader, parseScenario (instance_io.h), on arbitrary bytes.
// What it accepts must also survive a round trip through scenarioToYaml.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "fleet_planner/io/instance_io.h"
#include "fuzz_outcome.h"

namespace {

using namespace fleet_planner;

void checkSameRobots(const Instance& a, const Instance& b) {
  fuzz::check(a.robots.size() == b.robots.size(), "round trip changed the robot count");
  for (std::size_t i = 0; i < a.robots.size(); ++i) {
    const Robot& x = a.robots[i];
    const Robot& y = b.robots[i];
    fuzz::check(x.id == y.id, "round trip changed id '" + x.id + "' to '" + y.id + "'");
    fuzz::check(x.footprint == y.footprint, "round trip changed the footprint of '" + x.id + "'");
    fuzz::check(x.start == y.start && x.target == y.target,
                "round trip changed the poses of '" + x.id + "'");
  }
  fuzz::check(a.map_file == b.map_file, "round trip changed the map file");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  fuzz::parsesOrRejects("fuzz.yaml", [&] {
    const Instance instance = parseScenario(in, "fuzz.yaml");
    fuzz::check(!instance.robots.empty(), "scenario without robots accepted");
    for (const Robot& robot : instance.robots) {
      fuzz::check(!robot.id.empty(), "empty id accepted");
      fuzz::check(footprintProblem(robot.footprint).empty(), "bad footprint accepted");
    }
    const std::string yaml = scenarioToYaml(instance, instance.map_file);
    std::istringstream written(yaml);
    try {
      checkSameRobots(instance, parseScenario(written, "fuzz.yaml"));
    } catch (const ParseError& e) {
      fuzz::finding("parseScenario rejects what scenarioToYaml wrote: " + std::string(e.what()) +
                    "\n" + yaml);
    }
  });
  return 0;
}
