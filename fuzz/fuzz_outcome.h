#pragma once
/// What a fuzz target accepts as a normal outcome: the reader returns, or it throws the
/// ParseError its header documents, naming the input. Anything else (another exception type,
/// a ParseError that does not name the input, a broken invariant) aborts, which libFuzzer
/// reports as a crash and saves the input.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/runtime/resource_limits.h"

namespace fleet_planner::fuzz {

/// Aborts with `why` on stderr: a finding.
[[noreturn]] inline void finding(const std::string& why) {
  std::fprintf(stderr, "fuzz finding: %s\n", why.c_str());
  std::abort();
}

/// Aborts unless `condition`.
inline void check(bool condition, const std::string& why) {
  if (!condition) finding(why);
}

/// Runs `parse()`; a ParseError is the documented outcome for bad input, but it must name
/// `source` at the start of its message (every reader's "<file>:<line>: <reason>" style).
/// Returns true if `parse()` returned.
template <typename Parse>
bool parsesOrRejects(const std::string& source, Parse&& parse) {
  try {
    parse();
    return true;
  } catch (const ParseError& e) {
    const std::string what = e.what();
    check(what.compare(0, source.size(), source) == 0 && e.file() == source,
          "ParseError does not name the input '" + source + "': " + what);
    check(!e.reason().empty(), "ParseError without a reason: " + what);
    return false;
  } catch (const ResourceLimitError& e) {
    // The other documented outcome: a header claiming more cells than max_map_cells is refused
    // before anything is allocated, naming the input and the parameter.
    const std::string what = e.what();
    check(what.compare(0, source.size(), source) == 0 && what.find("max_map_cells") != std::string::npos,
          "ResourceLimitError does not name the input '" + source + "' and the parameter: " + what);
    return false;
  }
}

}  // namespace fleet_planner::fuzz
