// Backend options by name; see backend_parameters.h.
#include "fleet_planner/solvers/backend_parameters.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/solvers/solver.h"

namespace fleet_planner {

namespace {

std::string show(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

}  // namespace

void parseBackendParameter(const std::string& text, BackendParameters& into) {
  const auto dot = text.find('.');
  const auto eq = text.find('=');
  if (dot == std::string::npos || eq == std::string::npos || dot == 0 || dot + 1 >= eq) {
    throw InvalidInput("backend parameter '" + text + "': expected BACKEND.OPTION=VALUE (e.g. la_lns.neighborhood_size=12)");
  }
  const std::string value = text.substr(eq + 1);
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (value.empty() || used != value.size() || !std::isfinite(v)) {
    throw InvalidInput("backend parameter '" + text + "': value '" + value + "' is not a finite number");
  }
  into[text.substr(0, dot)][text.substr(dot + 1, eq - dot - 1)] = v;
}

OptionBinder::OptionBinder(std::string backend, const BackendOptionValues& values)
    : backend_(std::move(backend)), values_(values) {}

const double* OptionBinder::find(const char* name) {
  bound_.push_back(name);
  const auto it = values_.find(name);
  return it == values_.end() ? nullptr : &it->second;
}

void OptionBinder::reject(const char* name, double value, const std::string& rule) const {
  throw InvalidInput("backend parameter " + backend_ + "." + name + " must be " + rule + " (got " + show(value) + ")");
}

void OptionBinder::integer(const char* name, int& field, int min, int max) {
  long long wide = field;
  integer(name, wide, min, max);
  field = static_cast<int>(wide);
}

void OptionBinder::integer(const char* name, long long& field, long long min, long long max) {
  const double* v = find(name);
  if (v == nullptr) return;
  if (*v != std::floor(*v) || *v < static_cast<double>(min) || *v > static_cast<double>(max)) {
    reject(name, *v, "an integer in " + std::to_string(min) + ".." + std::to_string(max));
  }
  field = static_cast<long long>(*v);
}

void OptionBinder::number(const char* name, double& field, double min, double max) {
  const double* v = find(name);
  if (v == nullptr) return;
  if (!(*v >= min && *v <= max)) reject(name, *v, "in [" + show(min) + ", " + show(max) + "]");
  field = *v;
}

void OptionBinder::flag(const char* name, bool& field) {
  const double* v = find(name);
  if (v == nullptr) return;
  if (*v != 0.0 && *v != 1.0) reject(name, *v, "0 or 1 (false or true)");
  field = *v != 0.0;
}

void OptionBinder::finish() const {
  for (const auto& [name, value] : values_) {
    if (std::find(bound_.begin(), bound_.end(), name) != bound_.end()) continue;
    std::string known;
    for (const std::string& b : bound_) known += (known.empty() ? "" : ", ") + b;
    throw InvalidInput("backend " + backend_ + " has no option '" + name + "' (its options: " +
                       (known.empty() ? std::string("none") : known) + ")");
  }
}

void Solver::configure(const BackendOptionValues& values) { OptionBinder(name(), values).finish(); }

}  // namespace fleet_planner
