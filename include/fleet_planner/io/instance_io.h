#pragma once
/// Reading and writing instances: the benchmark's text format and fleet_planner's YAML
/// scenarios. Bad input throws ParseError naming the file and line; nothing is fixed up.
/// Neither reader checks positions against a map (no map is loaded here).
///
/// Benchmark format (the Layered LA-MAPF instance pools), one robot per non-blank line:
///
///     Circle   [id] r                       sx sy so  tx ty to
///     Block_2D [id] min_x min_y max_x max_y sx sy so  tx ty to
///
/// Fields are separated by blanks (a trailing '\r' is ignored). Either every robot line of a
/// file has the id column or none has; without it, a robot's id is its 0-based index among the
/// robots. Sizes are finite numbers; positions are integers (a number with an integer value,
/// such as 3.0, is accepted as that integer); headings (so, to) are 0..3
/// (0 = +x, 1 = -x, 2 = +y, 3 = -y). A file with no robots is an error.
///
/// Scenario format (YAML):
///
///     map: maps/warehouse.map          # optional; relative to this file's folder
///     robots:
///       - id: r1                         # required, unique, non-empty
///         footprint: {type: circle, radius: 1.5}
///         start: [10, 4, 0]              # x, y, heading (0 +x, 1 -x, 2 +y, 3 -y)
///         target: [30, 4, 2]
///       - id: r2
///         footprint: {type: block, min_x: -1.0, min_y: -0.5, max_x: 2.0, max_y: 0.5}
///         start: [5, 5, 1]
///         target: [8, 9, 3]
///       - id: r3
///         footprint: {type: polygon, points: [[1, 0], [-1, 1], [-1, -1]]}
///         start: [2, 2, 2]
///         target: [2, 9, 2]
///
/// Every key shown is required except `map`; other keys are errors. `robots` must list at
/// least one robot.
#include <iosfwd>
#include <string>

#include "fleet_planner/model/instance.h"

namespace fleet_planner {

/// Parses the benchmark format (see above). `source` names the input in messages; each robot's
/// source is "<source>:<line>". Instance::map_file is left empty. Throws ParseError(source,
/// line, reason) for an unknown kind, a wrong field count, a token that is not a finite number
/// (the whole token must parse: "1.5abc" is an error), a non-integer position, a heading outside
/// 0..3, a footprint that footprintProblem() rejects, a duplicate id, a file that mixes lines
/// with and without the id column, or a file without robots.
Instance parseBenchmarkInstance(std::istream& in, const std::string& source);

/// Reads a benchmark instance file (see parseBenchmarkInstance). Throws ParseError(path, 0,
/// ...) if the file cannot be opened.
Instance loadBenchmarkInstance(const std::string& path);

/// Parses a YAML scenario (see above) from `in`. `path` names the input in messages and is the
/// file whose folder a relative `map` entry is resolved against: Instance::map_file is the `map`
/// entry resolved that way (unchanged if absolute; empty if absent); each robot's source is
/// "<path>:<line of its list entry>". Throws ParseError(path, line, reason) for YAML syntax
/// errors, missing, unknown or repeated keys, missing, empty or duplicate ids, non-numbers,
/// non-integer positions, headings outside 0..3, unknown footprint types and footprints that
/// footprintProblem() rejects.
Instance parseScenario(std::istream& in, const std::string& path);

/// Reads a YAML scenario file (see parseScenario). Throws ParseError(path, 0, ...) if the file
/// cannot be opened.
Instance loadScenario(const std::string& path);

/// The instance as a YAML scenario (see above) that loadScenario reads back to the same
/// robots. `map_file_as_written` becomes the `map` entry verbatim (omitted if empty).
/// Numbers are written in their shortest exact form. Throws InvalidInput for a robot with an
/// empty id or a repeated id.
std::string scenarioToYaml(const Instance& instance, const std::string& map_file_as_written);

/// Writes scenarioToYaml(instance, instance.map_file) to `path` (map_file is written as it is,
/// not made relative to `path`). Throws InvalidInput naming the path if it cannot be written.
void saveScenario(const Instance& instance, const std::string& path);

/// Reads an instance in either format: a path ending in `.yaml` or `.yml` (any case) with
/// loadScenario, anything else with loadBenchmarkInstance.
Instance loadInstance(const std::string& path);

}  // namespace fleet_planner
