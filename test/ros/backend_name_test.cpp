// Which registered backend a request's name means. (Registers test-only names: the registry is
// global to this test binary, and other tests use la_cbs and la_lacam.)
#include <gtest/gtest.h>

#include "fleet_planner/ros/backend_loader.h"
#include "fleet_planner/solvers/cbs/la_cbs.h"
#include "fleet_planner/solvers/registry.h"

namespace fleet_planner::test {
namespace {

TEST(BackendNames, BuiltInsThenPluginsThenAmbiguity) {
  const auto factory = [] { return std::make_unique<LaCbs>(); };
  std::string why;
  EXPECT_EQ(resolveBackendName("la_cbs", &why), "la_cbs");
  EXPECT_EQ(resolveBackendName("nope", &why), "");
  EXPECT_NE(why.find("la_lacam"), std::string::npos) << why;

  registerSolver("zz_test_backend", factory);
  EXPECT_EQ(resolveBackendName("zz_test_backend", &why), "zz_test_backend");
  registerSolver("pkg_a/zz_test_backend", factory);
  EXPECT_EQ(resolveBackendName("zz_test_backend", &why), "pkg_a/zz_test_backend");  // the plugin is preferred
  EXPECT_EQ(resolveBackendName("pkg_a/zz_test_backend", &why), "pkg_a/zz_test_backend");

  registerSolver("pkg_b/zz_test_backend", factory);
  EXPECT_EQ(resolveBackendName("zz_test_backend", &why), "");
  EXPECT_NE(why.find("ambiguous"), std::string::npos) << why;
  EXPECT_EQ(resolveBackendName("pkg_b/zz_test_backend", &why), "pkg_b/zz_test_backend");
}

}  // namespace
}  // namespace fleet_planner::test
