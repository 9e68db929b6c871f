#pragma once
// Internal: numbers in the core's messages, formatted one way everywhere.
#include <iomanip>
#include <sstream>
#include <string>

namespace fleet_planner::io {

/// "12.3 MB" (one decimal).
inline std::string formatMb(double v) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(1) << v << " MB";
  return out.str();
}

/// Shortest form with up to 6 significant digits, as "%g": 4096, 0.5, 1e+12.
inline std::string formatNumber(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

}  // namespace fleet_planner::io
