#pragma once
/// Backends through pluginlib (the nav_core convention): every class a package exports for base
/// class fleet_planner::Solver (package.xml: <fleet_planner plugin="${prefix}/x.xml"/>) is
/// registered in the core's solver registry under its lookup name ("fleet_planner/la_cbs"), so
/// the layered planner creates it by name like any built-in backend.
#include <memory>
#include <string>
#include <vector>

namespace fleet_planner {

class BackendPlugins {
 public:
  /// Discovers the declared backends and registers a factory for each. Throws InvalidInput if the
  /// plugin system cannot be set up at all; a class that fails to load is reported by load().
  BackendPlugins();
  ~BackendPlugins();
  BackendPlugins(const BackendPlugins&) = delete;
  BackendPlugins& operator=(const BackendPlugins&) = delete;

  /// The lookup names declared to pluginlib.
  std::vector<std::string> declared() const;
  /// Creates one instance of each declared class (loading its library), and returns one line per
  /// class that cannot be created; such a class stays registered and fails when used.
  std::vector<std::string> load();

 private:
  struct Impl;
  std::shared_ptr<Impl> impl_;  // shared with the registered factories
};

/// The registered backend a request's name refers to: the name itself if registered; for a name
/// without '/', the one plugin "<package>/<name>" if there is exactly one (plugins first, so
/// "la_cbs" is fleet_planner's plugin once loaded), else the built-in of that name. Empty, with
/// the reason in *why_not (listing the known names), if there is none or it is ambiguous.
std::string resolveBackendName(const std::string& name, std::string* why_not);

}  // namespace fleet_planner
