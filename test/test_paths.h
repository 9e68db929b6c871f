#pragma once
/// Where the tests find their data files.
#include <string>

namespace fleet_planner::test {

/// Absolute path of a file under test/data.
std::string dataPath(const std::string& name);

}  // namespace fleet_planner::test
