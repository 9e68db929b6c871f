// The node's configuration check names each bad parameter; the defaults pass.
#include <gtest/gtest.h>

#include <cmath>

#include "fleet_planner/planning/planning_options.h"
#include "fleet_planner/ros/planner_config.h"

namespace fleet_planner::test {
namespace {

bool mentions(const std::vector<std::string>& errors, const std::string& what) {
  for (const auto& e : errors) {
    if (e.find(what) != std::string::npos) return true;
  }
  return false;
}

TEST(PlannerConfigCheck, DefaultsAreValid) { EXPECT_TRUE(checkPlannerConfig(PlannerConfig{}).empty()); }

TEST(PlannerConfigCheck, EachBadValueIsNamed) {
  struct Case {
    const char* parameter;
    void (*spoil)(PlannerConfig&);
  };
  const Case cases[] = {
      {"backend", [](PlannerConfig& c) { c.backend.clear(); }},
      {"time_limit", [](PlannerConfig& c) { c.time_limit = 0; }},
      {"time_limit", [](PlannerConfig& c) { c.time_limit = NAN; }},
      {"time_limit", [](PlannerConfig& c) { c.time_limit = c.max_time_limit + 1; }},
      {"max_time_limit", [](PlannerConfig& c) { c.max_time_limit = INFINITY; }},
      {"max_time_limit", [](PlannerConfig& c) { c.max_time_limit = 0; }},
      {"decomposition_steps", [](PlannerConfig& c) { c.decomposition_steps = 5; }},
      {"threads", [](PlannerConfig& c) { c.threads = -1; }},
      {"busy_policy", [](PlannerConfig& c) { c.busy_policy = "wait"; }},
      {"max_map_cells", [](PlannerConfig& c) { c.max_map_cells = 0; }},
      {"max_robots", [](PlannerConfig& c) { c.max_robots = -5; }},
      {"max_memory_mb", [](PlannerConfig& c) { c.max_memory_mb = 0; }},
      {"max_memory_mb", [](PlannerConfig& c) { c.max_memory_mb = NAN; }},
      {"occupied_threshold", [](PlannerConfig& c) { c.occupied_threshold = 101; }},
      {"unknown_policy", [](PlannerConfig& c) { c.unknown_policy = "maybe"; }},
      {"position_tolerance", [](PlannerConfig& c) { c.position_tolerance = -0.1; }},
      {"heading_tolerance", [](PlannerConfig& c) { c.heading_tolerance = INFINITY; }},
      {"sweep_tolerance", [](PlannerConfig& c) { c.sweep_tolerance = 0.3; }},
      {"sweep_tolerance", [](PlannerConfig& c) { c.sweep_tolerance = NAN; }},
      {"seconds_per_step", [](PlannerConfig& c) { c.seconds_per_step = 0; }},
      {"map_frame", [](PlannerConfig& c) { c.map_frame.clear(); }},
      {"base_frame", [](PlannerConfig& c) { c.base_frame.clear(); }},
      {"tf_timeout", [](PlannerConfig& c) { c.tf_timeout = -1; }},
      {"planned_frame", [](PlannerConfig& c) { c.planned_frame.clear(); }},
      {"playback_rate", [](PlannerConfig& c) { c.playback_rate = 0; }},
  };
  for (const Case& c : cases) {
    PlannerConfig config;
    c.spoil(config);
    const auto errors = checkPlannerConfig(config);
    ASSERT_EQ(errors.size(), 1u) << c.parameter;
    EXPECT_EQ(errors[0].rfind(c.parameter, 0), 0u) << errors[0];
  }
  PlannerConfig two;
  two.time_limit = -3;
  two.busy_policy = "later";
  const auto errors = checkPlannerConfig(two);
  EXPECT_EQ(errors.size(), 2u);
  EXPECT_TRUE(mentions(errors, "got -3"));
  EXPECT_TRUE(mentions(errors, "'reject' or 'queue'"));
}

TEST(PlannerConfigCheck, ResourceLimitsBecomeCoreLimits) {
  PlannerConfig config;
  EXPECT_EQ(config.max_map_cells, ResourceLimits{}.max_map_cells);
  EXPECT_EQ(config.max_robots, ResourceLimits{}.max_robots);
  EXPECT_EQ(config.max_memory_mb, ResourceLimits{}.max_memory_mb);
  config.max_map_cells = 1000;
  config.max_robots = 7;
  config.max_memory_mb = 512;
  const ResourceLimits limits = config.resourceLimits();
  EXPECT_EQ(limits.max_map_cells, 1000);
  EXPECT_EQ(limits.max_robots, 7);
  EXPECT_EQ(limits.max_memory_mb, 512);
  EXPECT_EQ(resourceLimitsProblem(limits), "");
}

TEST(PlannerConfigCheck, PoliciesBecomeCoreOptions) {
  PlannerConfig config;
  config.unknown_policy = "free";
  config.occupied_threshold = 50;
  EXPECT_TRUE(config.occupancyPolicy().unknown_is_free);
  EXPECT_EQ(config.occupancyPolicy().occupied_threshold, 50);
  EXPECT_DOUBLE_EQ(config.poseTolerance().heading, config.heading_tolerance);
}

TEST(PlannerConfigCheck, BackendsAndTheirParametersAreCheckedByName) {
  EXPECT_TRUE(checkPlannerBackends(PlannerConfig{}).empty());
  PlannerConfig config;
  config.fallback = "teleport";
  auto errors = checkPlannerBackends(config);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].rfind("fallback: ", 0), 0u) << errors[0];
  EXPECT_TRUE(mentions(errors, "teleport") && mentions(errors, "la_lns")) << errors[0];  // lists the known ones

  config = PlannerConfig{};
  config.backend = "la_cbs";  // serial, with a parallel fallback: planned at the chain's targets
  config.fallback = "la_lacam";
  EXPECT_TRUE(checkPlannerBackends(config).empty());

  config = PlannerConfig{};
  config.backend_parameters["la_lns"]["neighbourhood"] = 4;  // a typo
  errors = checkPlannerBackends(config);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].rfind("backend_parameters: ", 0), 0u) << errors[0];
  EXPECT_TRUE(mentions(errors, "neighbourhood") && mentions(errors, "neighborhood_size")) << errors[0];

  config.backend_parameters.clear();
  config.backend_parameters["la_lns"]["neighborhood_size"] = 0;  // out of range
  EXPECT_TRUE(mentions(checkPlannerBackends(config), "la_lns.neighborhood_size must be an integer in 1.."));
  config.backend_parameters["la_lns"]["neighborhood_size"] = 12;
  EXPECT_TRUE(checkPlannerBackends(config).empty());
}

TEST(PlannerConfigCheck, TheNodesDefaultsAreThePlanningDefaults) {
  const PlanningOptions node = planningOptions(PlannerConfig{});
  const PlanningOptions core;
  EXPECT_EQ(node.backend, core.backend);
  EXPECT_EQ(node.fallback, core.fallback);
  EXPECT_EQ(node.decompose, core.decompose);
  EXPECT_EQ(node.last_step, core.last_step);
  EXPECT_EQ(node.threads, core.threads);
  EXPECT_EQ(node.refine, core.refine);
  EXPECT_EQ(node.compress, core.compress);
  EXPECT_EQ(node.time_limit, core.time_limit);
  EXPECT_EQ(node.limits.max_memory_mb, core.limits.max_memory_mb);
  EXPECT_TRUE(node.backend_parameters.empty());
}

}  // namespace
}  // namespace fleet_planner::test
