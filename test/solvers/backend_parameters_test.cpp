// Backend options by name (backend_parameters.h): each backend takes its own, rejects unknown
// names and values out of range naming them, and an option set by name changes what it does.
#include <gtest/gtest.h>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/solvers/registry.h"
#include "solver_test_util.h"
#include "test_maps.h"

namespace fleet_planner::test {
namespace {

std::string configureError(const std::string& backend, const BackendOptionValues& values) {
  try {
    makeSolver(backend)->configure(values);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(BackendParameters, ParsesBackendOptionValueAndNamesBadText) {
  BackendParameters p;
  parseBackendParameter("la_lns.neighborhood_size=12", p);
  parseBackendParameter("la_cbs.bypass=0", p);
  EXPECT_EQ(p["la_lns"]["neighborhood_size"], 12);
  EXPECT_EQ(p["la_cbs"]["bypass"], 0);
  for (const char* bad : {"la_lns.neighborhood_size", "neighborhood_size=3", "la_lns.=3", "la_lns.x=", "la_lns.x=3y",
                          "la_lns.x=nan"}) {
    BackendParameters q;
    EXPECT_THROW(parseBackendParameter(bad, q), InvalidInput) << bad;
  }
}

TEST(BackendParameters, UnknownNamesAndValuesOutOfRangeAreNamed) {
  const std::pair<std::string, std::string> known[] = {
      {"la_cbs", "bypass"}, {"la_lacam", "restart_rate"}, {"la_lns", "neighborhood_size"}};
  for (const auto& [backend, option] : known) {
    const std::string error = configureError(backend, {{"no_such_option", 1}});
    EXPECT_NE(error.find(backend), std::string::npos) << error;
    EXPECT_NE(error.find("no_such_option"), std::string::npos) << error;
    EXPECT_NE(error.find(option), std::string::npos) << error;  // the known names are listed
  }
  EXPECT_NE(configureError("la_lns", {{"neighborhood_size", 0}}).find("la_lns.neighborhood_size"), std::string::npos);
  EXPECT_NE(configureError("la_lns", {{"neighborhood_size", 2.5}}).find("an integer"), std::string::npos);
  EXPECT_NE(configureError("la_cbs", {{"bypass", 2}}).find("0 or 1"), std::string::npos);
  EXPECT_NE(configureError("la_lacam", {{"restart_rate", 1.5}}).find("la_lacam.restart_rate"), std::string::npos);
  EXPECT_EQ(configureError("la_lns", {{"neighborhood_size", 4}, {"splice", 0}}), "");
  EXPECT_TRUE(checkBackendParameters({{"la_lns", {{"joint_size", 3}}}}).empty());
  EXPECT_EQ(checkBackendParameters({{"la_xyz", {}}}).size(), 1u);
}

TEST(BackendParameters, AnOptionSetByNameChangesTheSearch) {
  // Two robots trading places in a corridor with a pocket: every low-level search of LA-CBS
  // needs more than three nodes.
  World world(mapFromRows({".......", "@@@.@@@"}), {dot("a", {0, 0, 0}, {6, 0, 0}), dot("b", {6, 0, 1}, {0, 0, 1})});
  const Subproblem sub = allRobots(world, 10.0);
  const Outcome normal = solveWith("la_cbs", world, sub);
  ASSERT_TRUE(solvedValidly(normal));
  auto starved = makeSolver("la_cbs", {{"la_cbs", {{"max_low_level_nodes", 3}}}});
  const Outcome limited = solveWith(*starved, world, sub);
  EXPECT_FALSE(limited.result.success()) << describe(limited);
}

}  // namespace
}  // namespace fleet_planner::test
