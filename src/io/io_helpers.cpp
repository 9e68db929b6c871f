#include "io_helpers.h"

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "fleet_planner/runtime/errors.h"

namespace fleet_planner::io {

bool parseNumber(const std::string& token, double* value) {
  const char* begin = token.data();
  const char* end = token.data() + token.size();
  // from_chars rejects a leading '+', which people do write ("+1.5"); allow it before a digit.
  if (begin != end && *begin == '+' && begin + 1 != end && *(begin + 1) != '-' &&
      *(begin + 1) != '+') {
    ++begin;
  }
  if (begin == end) return false;
  double parsed = 0.0;
  const auto result = std::from_chars(begin, end, parsed);
  if (result.ec != std::errc() || result.ptr != end || !std::isfinite(parsed)) return false;
  *value = parsed;
  return true;
}

bool parseIntegral(const std::string& token, int* value) {
  double parsed = 0.0;
  if (!parseNumber(token, &parsed)) return false;
  if (parsed != std::floor(parsed)) return false;
  if (parsed < std::numeric_limits<int>::min() || parsed > std::numeric_limits<int>::max()) {
    return false;
  }
  *value = static_cast<int>(parsed);
  return true;
}

std::string formatNumber(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

// "\\xNN" for a control character.
std::string hexEscape(unsigned char c) {
  const char* digits = "0123456789abcdef";
  return std::string("\\x") + digits[c >> 4] + digits[c & 15];
}

std::string quoted(const std::string& text) {
  std::string out = "'";
  for (unsigned char c : text) {
    if (c < 0x20 || c == 0x7f) {
      out += hexEscape(c);
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "'";
}

namespace {

bool plainSafe(const std::string& text) {
  if (text.empty() || text == "~" || text == "null" || text == "Null" || text == "NULL") {
    return false;
  }
  const auto word = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  };
  if (!word(text[0])) return false;
  for (char c : text) {
    if (!word(c) && c != '.' && c != '/' && c != '-') return false;
  }
  return true;
}

std::string nodeKind(const YAML::Node& node) {
  if (node.IsNull()) return "nothing";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return quoted(node.Scalar());
}

}  // namespace

std::string yamlScalar(const std::string& text) {
  if (plainSafe(text)) return text;
  std::string out = "\"";
  for (unsigned char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c == 0x7f) {
      out += hexEscape(c);
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

bool hasYamlExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".yaml" || ext == ".yml";
}

std::string resolveRelativeTo(const std::string& path, const std::string& relative) {
  const std::filesystem::path rel(relative);
  if (rel.is_absolute()) return relative;
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty()) return relative;
  return (folder / rel).lexically_normal().string();
}

void writeTextFile(const std::string& path, const std::string& text) {
  errno = 0;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) {
    const std::string why = errno != 0 ? std::string(": ") + std::strerror(errno) : "";
    throw InvalidInput("cannot open '" + path + "' for writing" + why);
  }
  out << text;
  out.flush();
  if (!out) throw InvalidInput("writing '" + path + "' failed");
}

YAML::Node parseYaml(std::istream& in, const std::string& path) {
  try {
    return YAML::Load(in);
  } catch (const YAML::ParserException& e) {
    throw ParseError(path, e.mark.is_null() ? 0 : e.mark.line + 1, "YAML syntax error: " + e.msg);
  } catch (const YAML::Exception& e) {
    throw ParseError(path, e.mark.is_null() ? 0 : e.mark.line + 1, "YAML error: " + e.msg);
  }
}

YAML::Node loadYamlFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ParseError(path, 0, "cannot open file");
  return parseYaml(in, path);
}

int yamlLine(const YAML::Node& node, int fallback) {
  if (!node.IsDefined()) return fallback;
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? fallback : mark.line + 1;
}

YamlMapping::YamlMapping(const YAML::Node& node, std::string file, int line, std::string what,
                         const std::vector<std::string>& allowed)
    : file_(std::move(file)), line_(line), what_(std::move(what)) {
  if (!node.IsMap()) {
    throw ParseError(file_, line_, what_ + " must be a mapping, got " + nodeKind(node));
  }
  for (auto it = node.begin(); it != node.end(); ++it) {
    const int key_line = yamlLine(it->first, line_);
    if (!it->first.IsScalar()) {
      throw ParseError(file_, key_line, "a key of " + what_ + " is not a string");
    }
    const std::string key = it->first.Scalar();
    bool known = false;
    for (const auto& name : allowed) known = known || name == key;
    if (!known) {
      std::string list;
      for (const auto& name : allowed) list += (list.empty() ? "" : ", ") + name;
      throw ParseError(file_, key_line,
                       "unknown key " + quoted(key) + " in " + what_ + " (expected " + list + ")");
    }
    if (fields_.count(key) != 0) {
      throw ParseError(file_, key_line, "duplicate key " + quoted(key) + " in " + what_);
    }
    fields_[key] = YamlField{it->second, key_line};
  }
}

const YamlField* YamlMapping::find(const std::string& key) const {
  const auto it = fields_.find(key);
  return it == fields_.end() ? nullptr : &it->second;
}

const YamlField& YamlMapping::require(const std::string& key) const {
  const YamlField* field = find(key);
  if (field == nullptr) throw ParseError(file_, line_, what_ + " has no " + quoted(key));
  return *field;
}

double YamlMapping::number(const YamlField& field, const std::string& what) const {
  return yamlNumber(field.node, file_, field.line, what);
}

int YamlMapping::integral(const YamlField& field, const std::string& what) const {
  return yamlIntegral(field.node, file_, field.line, what);
}

std::string YamlMapping::string(const YamlField& field, const std::string& what) const {
  if (!field.node.IsScalar() || field.node.Scalar().empty()) {
    throw ParseError(file_, field.line,
                     what + " must be a non-empty string, got " + nodeKind(field.node));
  }
  return field.node.Scalar();
}

double yamlNumber(const YAML::Node& node, const std::string& file, int line,
                  const std::string& what) {
  double value = 0.0;
  if (!node.IsScalar() || !parseNumber(node.Scalar(), &value)) {
    throw ParseError(file, line, what + " must be a finite number, got " + nodeKind(node));
  }
  return value;
}

int yamlIntegral(const YAML::Node& node, const std::string& file, int line,
                 const std::string& what) {
  const double value = yamlNumber(node, file, line, what);
  int result = 0;
  if (!parseIntegral(node.Scalar(), &result)) {
    throw ParseError(file, line, what + " must be an integer, got " + formatNumber(value));
  }
  return result;
}

}  // namespace fleet_planner::io
