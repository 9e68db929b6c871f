#pragma once
/// Typed errors for invalid input. The library throws these only for malformed input or
/// misuse; planning outcomes are returned as values.
#include <stdexcept>
#include <string>

namespace fleet_planner {

/// Base of every error the library throws for bad input.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A file could not be read or parsed. what() = "<file>:<line>: <reason>" (line 0 = whole file).
class ParseError : public InputError {
 public:
  ParseError(std::string file, int line, std::string reason);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string file_;
  int line_;
  std::string reason_;
};

/// A well-formed input that makes no sense: a footprint larger than the map, a start off the
/// map, a NaN size. what() names the robot (and where it came from, when known).
class InvalidInput : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace fleet_planner
