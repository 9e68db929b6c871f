#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {

namespace {
std::string formatParseError(const std::string& file, int line, const std::string& reason) {
  if (line > 0) return file + ":" + std::to_string(line) + ": " + reason;
  return file + ": " + reason;
}
}  // namespace

ParseError::ParseError(std::string file, int line, std::string reason)
    : InputError(formatParseError(file, line, reason)),
      file_(std::move(file)),
      line_(line),
      reason_(std::move(reason)) {}

}  // namespace fleet_planner
