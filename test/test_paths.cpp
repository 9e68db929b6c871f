#include "test_paths.h"

namespace fleet_planner::test {

std::string dataPath(const std::string& name) { return std::string(FLEET_PLANNER_TEST_DATA) + "/" + name; }

std::string fuzzRegressionPath(const std::string& name) {
  return std::string(FLEET_PLANNER_TEST_DATA) + "/../fuzz/regressions/" + name;
}

}  // namespace fleet_planner::test
