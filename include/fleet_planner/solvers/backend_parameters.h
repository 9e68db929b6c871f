#pragma once
/// Backend options set by name: from the node's `backend_parameters` ({backend: {option: value}})
/// and the CLI's `--backend-param BACKEND.OPTION=VALUE`. Every value is a number (booleans are
/// 0 or 1); each backend binds its names to the fields of its options struct (OptionBinder) and
/// rejects unknown names and values out of range with the backend, the option and the rule named.
#include <map>
#include <string>
#include <vector>

namespace fleet_planner {

/// One backend's options: name -> value.
using BackendOptionValues = std::map<std::string, double>;
/// Options per backend name.
using BackendParameters = std::map<std::string, BackendOptionValues>;

/// Parses "BACKEND.OPTION=VALUE" into `into`. Throws InvalidInput naming the text for a missing
/// dot, equals sign or a value that is not a number.
void parseBackendParameter(const std::string& text, BackendParameters& into);

/// Binds a backend's option names to the fields of its options struct and applies `values`:
///   OptionBinder bind("la_lns", values);
///   bind.integer("neighborhood_size", o.neighborhood_size, 1, 10000);
///   bind.finish();  // throws for names not bound, listing the bound ones
/// Each bind throws InvalidInput for a value out of its range (or not whole, for integers).
class OptionBinder {
 public:
  OptionBinder(std::string backend, const BackendOptionValues& values);
  void integer(const char* name, int& field, int min, int max);
  void integer(const char* name, long long& field, long long min, long long max);
  void number(const char* name, double& field, double min, double max);
  void flag(const char* name, bool& field);
  void finish() const;

 private:
  const double* find(const char* name);
  [[noreturn]] void reject(const char* name, double value, const std::string& rule) const;
  std::string backend_;
  const BackendOptionValues& values_;
  std::vector<std::string> bound_;
};

}  // namespace fleet_planner
