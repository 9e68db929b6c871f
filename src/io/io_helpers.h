#pragma once
/// Internal helpers shared by the file readers and writers (map_io, instance_io, plan_io):
/// strict number parsing, number and string formatting, YAML access with line numbers.
/// Not part of the public API.
#include <yaml-cpp/yaml.h>

#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace fleet_planner::io {

/// Parses the whole token as a finite double ("1.5abc", "nan", "inf", "" fail).
bool parseNumber(const std::string& token, double* value);

/// Parses the whole token as a number with an integer value in the int range ("3", "3.0" and
/// "3e0" pass; "3.5", "1e20", "x" fail).
bool parseIntegral(const std::string& token, int* value);

/// Shortest decimal form that reads back as exactly `value` ("1.5", "-0.25", "2").
std::string formatNumber(double value);

/// `text` in single quotes with non-printable bytes as \xNN, for messages.
std::string quoted(const std::string& text);

/// `text` as a YAML scalar: plain when that reads back as the same string, else double-quoted.
std::string yamlScalar(const std::string& text);

/// True if `path` ends in ".yaml" or ".yml" (any case).
bool hasYamlExtension(const std::string& path);

/// The folder part of `path` joined with `relative` (returned unchanged if absolute).
std::string resolveRelativeTo(const std::string& path, const std::string& relative);

/// Writes `text` to `path`; throws InvalidInput naming the path if that fails.
void writeTextFile(const std::string& path, const std::string& text);

/// Parses YAML text; a syntax error throws ParseError(path, line, reason), `path` naming the
/// input in messages.
YAML::Node parseYaml(std::istream& in, const std::string& path);

/// Reads a YAML file; a missing file or a syntax error throws ParseError(path, line, reason).
YAML::Node loadYamlFile(const std::string& path);

/// 1-based line of a parsed node, or `fallback` when it has none.
int yamlLine(const YAML::Node& node, int fallback);

/// A mapping value and the 1-based line of its key.
struct YamlField {
  YAML::Node node;
  int line = 0;
};

/// The entries of a YAML mapping, checked against a list of allowed keys. Throws ParseError if
/// the node is not a mapping, a key is not a string, a key repeats or a key is not allowed.
class YamlMapping {
 public:
  /// `what` names the mapping in messages ("robot 2", "the map file"); `line` is where it
  /// starts (1-based).
  YamlMapping(const YAML::Node& node, std::string file, int line, std::string what,
              const std::vector<std::string>& allowed);

  /// The field, or nullptr if the key is absent.
  const YamlField* find(const std::string& key) const;
  /// The field; throws ParseError "<what> has no '<key>'" at the mapping's line if absent.
  const YamlField& require(const std::string& key) const;
  const std::string& file() const { return file_; }
  int line() const { return line_; }

  /// A finite number; `what` names it in messages.
  double number(const YamlField& field, const std::string& what) const;
  /// A number with an integer value.
  int integral(const YamlField& field, const std::string& what) const;
  /// A non-empty string scalar.
  std::string string(const YamlField& field, const std::string& what) const;

 private:
  std::string file_;
  int line_;
  std::string what_;
  std::map<std::string, YamlField> fields_;
};

/// A finite number from a scalar node; ParseError(file, line, ...) otherwise.
double yamlNumber(const YAML::Node& node, const std::string& file, int line,
                  const std::string& what);
/// An integer-valued number from a scalar node; ParseError(file, line, ...) otherwise.
int yamlIntegral(const YAML::Node& node, const std::string& file, int line,
                 const std::string& what);

}  // namespace fleet_planner::io
