#pragma once
/// Where the tests find their data files.
#include <string>

namespace fleet_planner::test {

/// Absolute path of a file under test/data.
std::string dataPath(const std::string& name);

/// Absolute path of an input a fuzz target once failed on: test/fuzz/regressions/<name>, with
/// name = "<target>/<file>".
std::string fuzzRegressionPath(const std::string& name);

}  // namespace fleet_planner::test
