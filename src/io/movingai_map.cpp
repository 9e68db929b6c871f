#include <algorithm>
#include <charconv>
#include <cstdint>
#include <fstream>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/io/map_io.h"
#include "io_helpers.h"

namespace fleet_planner {

namespace {

constexpr int kMaxSide = 100000;
constexpr long long kMaxCells = 1LL << 28;

/// Reads lines, counting them (1-based) and dropping a trailing '\r'.
class LineReader {
 public:
  explicit LineReader(std::istream& in) : in_(in) {}
  bool next(std::string* line) {
    if (!std::getline(in_, *line)) return false;
    ++number_;
    if (!line->empty() && line->back() == '\r') line->pop_back();
    return true;
  }
  int number() const { return number_; }

 private:
  std::istream& in_;
  int number_ = 0;
};

std::vector<std::string> splitWords(const std::string& line) {
  std::istringstream split(line);
  std::vector<std::string> words;
  for (std::string word; split >> word;) words.push_back(word);
  return words;
}

/// 1 for blocked, 0 for passable, -1 for a character that is not a map character.
int classify(char c) {
  switch (c) {
    case '.':
    case 'G':
    case 'S':
      return 0;
    case '@':
    case 'O':
    case 'T':
    case 'W':
      return 1;
    default:
      return -1;
  }
}

int parseSide(const std::string& word, const std::string& name, const std::string& source,
              int line) {
  int value = 0;
  const auto result = std::from_chars(word.data(), word.data() + word.size(), value);
  if (result.ec != std::errc() || result.ptr != word.data() + word.size() || value < 1 ||
      value > kMaxSide) {
    throw ParseError(source, line,
                     name + " must be an integer in [1, " + std::to_string(kMaxSide) + "], got " +
                         io::quoted(word));
  }
  return value;
}

}  // namespace

GridMap parseMovingAiMap(std::istream& in, const std::string& source, const ResourceLimits& limits) {
  LineReader reader(in);
  std::string line;
  const auto nextHeaderLine = [&](const std::string& expected) {
    if (!reader.next(&line)) {
      throw ParseError(source, 0, "file ends before the header line " + expected);
    }
    return splitWords(line);
  };

  std::vector<std::string> words = nextHeaderLine("'type <name>'");
  if (words.empty() || words[0] != "type") {
    throw ParseError(source, reader.number(),
                     "expected the header line 'type <name>', got " + io::quoted(line));
  }
  int height = 0;
  int width = 0;
  for (int i = 0; i < 2; ++i) {
    words = nextHeaderLine("'height H' or 'width W'");
    if (words.size() != 2 || (words[0] != "height" && words[0] != "width")) {
      throw ParseError(source, reader.number(),
                       "expected the header line 'height H' or 'width W', got " + io::quoted(line));
    }
    int& side = words[0] == "height" ? height : width;
    if (side != 0) throw ParseError(source, reader.number(), "repeated '" + words[0] + "' line");
    side = parseSide(words[1], words[0], source, reader.number());
  }
  words = nextHeaderLine("'map'");
  if (words.size() != 1 || words[0] != "map") {
    throw ParseError(source, reader.number(),
                     "expected the header line 'map', got " + io::quoted(line));
  }
  if (static_cast<long long>(width) * height > kMaxCells) {
    throw ParseError(source, 0,
                     "map of " + std::to_string(width) + " x " + std::to_string(height) +
                         " cells is larger than the supported 2^28 cells");
  }

  checkMapCells(width, height, limits, source);
  // The cells grow with the rows actually read, never ahead of them: a header alone cannot make
  // the reader allocate the large map it claims.
  const std::size_t cells = static_cast<std::size_t>(width) * height;
  std::vector<std::uint8_t> blocked;
  for (int y = 0; y < height; ++y) {
    if (!reader.next(&line)) {
      throw ParseError(
          source, reader.number(),
          "file ends after " + std::to_string(y) + " of " + std::to_string(height) + " map rows");
    }
    for (std::size_t column = 0; column < line.size(); ++column) {
      if (classify(line[column]) < 0) {
        throw ParseError(source, reader.number(),
                         "unknown character " + io::quoted(std::string(1, line[column])) +
                             " at column " + std::to_string(column + 1));
      }
    }
    if (line.size() != static_cast<std::size_t>(width)) {
      throw ParseError(source, reader.number(),
                       "map row " + std::to_string(y) + " has " + std::to_string(line.size()) +
                           " characters, expected " + std::to_string(width));
    }
    if (blocked.capacity() < blocked.size() + width) {
      blocked.reserve(std::min(cells, 2 * blocked.capacity() + width));
    }
    for (int x = 0; x < width; ++x) blocked.push_back(static_cast<std::uint8_t>(classify(line[x])));
  }
  while (reader.next(&line)) {
    if (line.find_first_not_of(" \t") != std::string::npos) {
      throw ParseError(source, reader.number(),
                       "extra line after the " + std::to_string(height) + " map rows");
    }
  }
  GridMap map(width, height, std::move(blocked));
  map.setSource(source);
  return map;
}

GridMap loadMovingAiMap(const std::string& path, const ResourceLimits& limits) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ParseError(path, 0, "cannot open file");
  return parseMovingAiMap(in, path, limits);
}

}  // namespace fleet_planner
