#include "pgm_image.h"

#include <algorithm>
#include <fstream>
#include <iterator>

#include "fleet_planner/runtime/errors.h"
#include "io_helpers.h"

namespace fleet_planner::io {

namespace {

constexpr long long kMaxSide = 100000;
constexpr long long kMaxPixels = 1LL << 28;

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}
bool isDigit(char c) { return c >= '0' && c <= '9'; }

/// Walks the file's bytes, counting lines (1-based) for messages.
class Cursor {
 public:
  Cursor(const std::string& path, const std::string& data) : path_(path), data_(data) {}

  bool atEnd() const { return pos_ >= data_.size(); }
  std::size_t pos() const { return pos_; }
  std::size_t remaining() const { return data_.size() - pos_; }
  int line() const { return line_; }
  char peek() const { return data_[pos_]; }
  void advance() {
    if (data_[pos_] == '\n') ++line_;
    ++pos_;
  }

  /// Skips whitespace and `#` comments (to the end of their line).
  void skipSpaceAndComments() {
    while (!atEnd()) {
      if (isSpace(peek())) {
        advance();
      } else if (peek() == '#') {
        while (!atEnd() && peek() != '\n') advance();
      } else {
        break;
      }
    }
  }

  /// Skips a `#` comment through the carriage return or newline that ends it.
  void skipComment() {
    while (!atEnd() && peek() != '\n' && peek() != '\r') advance();
    if (!atEnd()) advance();
  }

  /// Reads a decimal number in [low, high] after optional whitespace and comments; `name()`
  /// names it in messages (a function so that the message is only built on error).
  template <typename Name>
  long long readNumber(const Name& name, long long low, long long high) {
    skipSpaceAndComments();
    if (atEnd()) throw ParseError(path_, 0, "file ends before the " + name());
    if (!isDigit(peek())) {
      throw ParseError(path_, line_,
                       "expected the " + name() + ", found " + quoted(std::string(1, peek())));
    }
    long long value = 0;
    while (!atEnd() && isDigit(peek())) {
      value = std::min(value * 10 + (peek() - '0'), high + 1);
      advance();
    }
    if (!atEnd() && !isSpace(peek()) && peek() != '#') {
      throw ParseError(
          path_, line_,
          "unexpected character " + quoted(std::string(1, peek())) + " after the " + name());
    }
    if (value < low || value > high) {
      throw ParseError(
          path_, line_,
          name() + " must be in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
    }
    return value;
  }

 private:
  const std::string& path_;
  const std::string& data_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

}  // namespace

PgmImage parsePgm(const std::string& data, const std::string& path, const ResourceLimits* limits) {
  if (data.size() < 2 || data[0] != 'P' || (data[1] != '2' && data[1] != '5') ||
      (data.size() > 2 && !isSpace(data[2]) && data[2] != '#')) {
    throw ParseError(path, 0, "only PGM images are supported (P2 or P5 netpbm graymaps)");
  }
  const bool binary = data[1] == '5';
  Cursor cursor(path, data);
  cursor.advance();
  cursor.advance();

  PgmImage image;
  image.width =
      static_cast<int>(cursor.readNumber([] { return std::string("image width"); }, 1, kMaxSide));
  image.height =
      static_cast<int>(cursor.readNumber([] { return std::string("image height"); }, 1, kMaxSide));
  image.maxval =
      static_cast<int>(cursor.readNumber([] { return std::string("maxval"); }, 1, 65535));
  const long long count = static_cast<long long>(image.width) * image.height;
  if (count > kMaxPixels) {
    throw ParseError(path, cursor.line(),
                     "image of " + std::to_string(image.width) + " x " +
                         std::to_string(image.height) + " pixels is larger than 2^28 pixels");
  }
  if (limits != nullptr) checkMapCells(image.width, image.height, *limits, path);
  // The pixels are allocated only for data that is there: the header alone cannot make the
  // reader allocate the large image it claims.
  if (binary) {
    // The header ends with a single whitespace byte after maxval; comments may come before it
    // (the newline that ends a comment belongs to the comment).
    while (!cursor.atEnd() && cursor.peek() == '#') cursor.skipComment();
    if (cursor.atEnd()) throw ParseError(path, 0, "image data is missing");
    if (!isSpace(cursor.peek())) {
      throw ParseError(path, cursor.line(),
                       "expected a whitespace byte between the header and the pixels, found " +
                           quoted(std::string(1, cursor.peek())));
    }
    cursor.advance();
    const std::size_t bytes_per_pixel = image.maxval > 255 ? 2 : 1;
    const std::size_t needed = static_cast<std::size_t>(count) * bytes_per_pixel;
    if (cursor.remaining() < needed) {
      throw ParseError(path, 0,
                       "image data is truncated: expected " + std::to_string(needed) +
                           " bytes of pixels, found " + std::to_string(cursor.remaining()));
    }
    if (cursor.remaining() > needed) {
      throw ParseError(path, 0,
                       "extra data after the " + std::to_string(needed) + " bytes of pixels");
    }
    const auto* bytes = reinterpret_cast<const unsigned char*>(data.data() + cursor.pos());
    image.pixels.resize(static_cast<std::size_t>(count));
    for (long long i = 0; i < count; ++i) {
      const unsigned value =
          bytes_per_pixel == 2 ? (bytes[2 * i] << 8) | bytes[2 * i + 1] : bytes[i];
      if (value > static_cast<unsigned>(image.maxval)) {
        throw ParseError(path, 0,
                         "pixel (column " + std::to_string(i % image.width) + ", row " +
                             std::to_string(i / image.width) + ") has value " +
                             std::to_string(value) + " above maxval " +
                             std::to_string(image.maxval));
      }
      image.pixels[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>(value);
    }
    return image;
  }

  // Each value takes at least one byte.
  image.pixels.reserve(std::min(static_cast<std::size_t>(count), cursor.remaining()));
  for (long long i = 0; i < count; ++i) {
    cursor.skipSpaceAndComments();
    if (cursor.atEnd()) {
      throw ParseError(path, 0,
                       "image data is truncated: found " + std::to_string(i) + " of " +
                           std::to_string(count) + " pixel values");
    }
    const auto name = [&] {
      return "value of pixel (column " + std::to_string(i % image.width) + ", row " +
             std::to_string(i / image.width) + ")";
    };
    image.pixels.push_back(static_cast<std::uint16_t>(cursor.readNumber(name, 0, image.maxval)));
  }
  cursor.skipSpaceAndComments();
  if (!cursor.atEnd()) {
    throw ParseError(path, cursor.line(),
                     "extra data after the " + std::to_string(count) + " pixel values");
  }
  return image;
}

PgmImage readPgm(const std::string& path, const ResourceLimits* limits) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ParseError(path, 0, "cannot open file");
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parsePgm(data, path, limits);
}

}  // namespace fleet_planner::io
