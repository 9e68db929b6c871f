#include "fleet_planner/ros/backend_loader.h"

#include <pluginlib/class_loader.hpp>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/solvers/registry.h"

namespace fleet_planner {

namespace {

/// A pluginlib instance behind the core's Solver interface (the registry owns Solvers by
/// unique_ptr; pluginlib hands out its own pointers, which must not outlive the loader).
class PluginSolver : public Solver {
 public:
  PluginSolver(std::shared_ptr<Solver> impl, std::shared_ptr<const void> keep_loader)
      : impl_(std::move(impl)), keep_loader_(std::move(keep_loader)) {}
  std::string name() const override { return impl_->name(); }
  bool avoidsMovingObstacles() const override { return impl_->avoidsMovingObstacles(); }
  void configure(const BackendOptionValues& values) override { impl_->configure(values); }
  SolveResult solve(const Subproblem& problem) override { return impl_->solve(problem); }

 private:
  std::shared_ptr<Solver> impl_;
  std::shared_ptr<const void> keep_loader_;
};

}  // namespace

struct BackendPlugins::Impl {
  pluginlib::ClassLoader<Solver> loader{"fleet_planner", "fleet_planner::Solver"};
};

BackendPlugins::BackendPlugins() {
  try {
    impl_ = std::make_shared<Impl>();
  } catch (const std::exception& e) {
    throw InvalidInput(std::string("pluginlib: cannot list fleet_planner backends: ") + e.what());
  }
  std::weak_ptr<Impl> weak = impl_;
  for (const std::string& name : impl_->loader.getDeclaredClasses()) {
    registerSolver(name, [weak, name]() -> std::unique_ptr<Solver> {
      const auto impl = weak.lock();
      if (!impl) throw InvalidInput("backend '" + name + "': its plugin loader is gone");
      try {
        return std::make_unique<PluginSolver>(impl->loader.createSharedInstance(name), impl);
      } catch (const pluginlib::PluginlibException& e) {
        throw InvalidInput("backend '" + name + "' cannot be loaded: " + e.what());
      }
    });
  }
}

BackendPlugins::~BackendPlugins() = default;

std::vector<std::string> BackendPlugins::declared() const { return impl_->loader.getDeclaredClasses(); }

std::vector<std::string> BackendPlugins::load() {
  std::vector<std::string> problems;
  for (const std::string& name : declared()) {
    try {
      makeSolver(name);
    } catch (const std::exception& e) {
      problems.push_back(e.what());
    }
  }
  return problems;
}

std::string resolveBackendName(const std::string& name, std::string* why_not) {
  const std::vector<std::string> known = solverNames();
  std::vector<std::string> plugins;  // "<package>/<name>"
  bool exact = false;
  for (const std::string& k : known) {
    exact = exact || k == name;
    const auto slash = k.rfind('/');
    if (name.find('/') == std::string::npos && slash != std::string::npos && k.substr(slash + 1) == name) {
      plugins.push_back(k);
    }
  }
  if (plugins.size() == 1) return plugins.front();
  if (exact && plugins.empty()) return name;
  std::string list;
  for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
  if (why_not != nullptr) {
    *why_not = plugins.empty() ? "no backend named '" + name + "'; known backends: " + list
                               : "backend name '" + name + "' is ambiguous; say which: " + list;
  }
  return {};
}

}  // namespace fleet_planner
