// Tests of plan_io.h: plans as YAML.
#include "fleet_planner/io/plan_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {
namespace {

/// Runs `f` and checks that it throws a ParseError naming `file` and `line` (as "file:line:"
/// unless line is 0) whose message contains `word`.
template <typename F>
void expectParseError(F&& f, const std::string& file, int line, const std::string& word) {
  try {
    f();
    ADD_FAILURE() << "no ParseError; expected " << file << ":" << line << " " << word;
  } catch (const ParseError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file), std::string::npos) << what;
    EXPECT_EQ(e.line(), line) << what;
    if (line > 0) {
      EXPECT_NE(what.find(file + ":" + std::to_string(line) + ":"), std::string::npos) << what;
    }
    EXPECT_NE(what.find(word), std::string::npos) << what;
  }
}

std::string scratchPath(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / "fleet_planner_plan_io_test";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

std::string scratchFile(const std::string& name, const std::string& content) {
  const std::string path = scratchPath(name);
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

/// Two robots: r1 from (0,0,0) to (2,0,0), r2 from (5,5,2) to (5,6,2).
Instance twoRobots() {
  Instance instance;
  instance.robots.push_back(
      Robot{"r1", Footprint::circle(0.5), GridPose{0, 0, 0}, GridPose{2, 0, 0}, ""});
  instance.robots.push_back(
      Robot{"r2", Footprint::circle(0.5), GridPose{5, 5, 2}, GridPose{5, 6, 2}, ""});
  return instance;
}

Plan twoPaths() {
  Plan plan;
  plan.paths.push_back({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  plan.paths.push_back({{5, 5, 2}, {5, 6, 2}});
  return plan;
}

TEST(PlanIo, WritesTheDocumentedFormat) {
  EXPECT_EQ(planToYaml(twoRobots(), twoPaths()),
            "# fleet_planner plan: each path lists [x, y, heading] at time steps 0, 1, 2, ...\n"
            "format: fleet_planner/plan/1\n"
            "soc: 4\n"
            "makespan: 3\n"
            "robots:\n"
            "  - id: r1\n"
            "    cost: 3\n"
            "    path: [[0, 0, 0], [1, 0, 0], [1, 0, 0], [2, 0, 0]]\n"
            "  - id: r2\n"
            "    cost: 1\n"
            "    path: [[5, 5, 2], [5, 6, 2]]\n");
}

TEST(PlanIo, WritesMinusOneForAPathThatMissesItsTarget) {
  Plan plan = twoPaths();
  plan.paths[1] = {{5, 5, 2}, {5, 6, 3}};
  const std::string yaml = planToYaml(twoRobots(), plan);
  EXPECT_NE(yaml.find("soc: -1\nmakespan: -1\n"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("    cost: 3\n"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("    cost: -1\n"), std::string::npos) << yaml;
  const std::string path = scratchPath("missed_target.yaml");
  savePlan(twoRobots(), plan, path);
  EXPECT_EQ(loadPlan(path, twoRobots()).paths, plan.paths);
}

TEST(PlanIo, RoundTripsThroughAFile) {
  const std::string path = scratchPath("plan.yaml");
  savePlan(twoRobots(), twoPaths(), path);
  EXPECT_EQ(loadPlan(path, twoRobots()).paths, twoPaths().paths);
}

TEST(PlanIo, RecordsThatBackwardMovesWereAllowed) {
  const std::string path = scratchPath("backward.yaml");
  savePlan(twoRobots(), twoPaths(), path, /*backward_moves=*/true);
  EXPECT_NE(planToYaml(twoRobots(), twoPaths(), true).find("\nbackward_moves: true\nrobots:\n"), std::string::npos);
  bool backward = false;
  EXPECT_EQ(loadPlan(path, twoRobots(), &backward).paths, twoPaths().paths);
  EXPECT_TRUE(backward);
  savePlan(twoRobots(), twoPaths(), path);
  EXPECT_EQ(loadPlan(path, twoRobots(), &backward).paths, twoPaths().paths);
  EXPECT_FALSE(backward);
  const std::string bad = scratchFile("backward_bad.yaml",
                                      "format: fleet_planner/plan/1\n"
                                      "backward_moves: maybe\n"
                                      "robots: []\n");
  expectParseError([&] { loadPlan(bad, twoRobots()); }, bad, 2, "backward_moves must be true or false");
}

TEST(PlanIo, ReturnsPathsInInstanceOrderAndMetricsAreOptional) {
  const std::string path = scratchFile("reordered.yaml",
                                       "format: fleet_planner/plan/1\n"
                                       "robots:\n"
                                       "  - id: r2\n"
                                       "    path: [[5, 5, 2], [5, 6, 2]]\n"
                                       "  - id: r1\n"
                                       "    path:\n"
                                       "      - [0, 0, 0]\n"
                                       "      - [1, 0, 0]\n"
                                       "      - [1, 0, 0]\n"
                                       "      - [2, 0, 0]\n");
  EXPECT_EQ(loadPlan(path, twoRobots()).paths, twoPaths().paths);
}

TEST(PlanIo, RefusesToWriteBadPlans) {
  Plan plan = twoPaths();
  try {
    savePlan(twoRobots(), plan, "/no_such_dir_fleet_planner/plan.yaml");
    ADD_FAILURE() << "no InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("/no_such_dir_fleet_planner/plan.yaml"),
              std::string::npos);
  }
  plan.paths[1].clear();
  EXPECT_THROW(planToYaml(twoRobots(), plan), InvalidInput);
  plan.paths.pop_back();
  EXPECT_THROW(planToYaml(twoRobots(), plan), InvalidInput);
}

TEST(PlanIo, RejectsBadPlans) {
  const std::string head = "format: fleet_planner/plan/1\nsoc: 4\nmakespan: 3\nrobots:\n";
  const std::string r1 =
      "  - id: r1\n    cost: 3\n    path: [[0, 0, 0], [1, 0, 0], [1, 0, 0], [2, 0, 0]]\n";
  const std::string r2 = "  - id: r2\n    cost: 1\n    path: [[5, 5, 2], [5, 6, 2]]\n";
  struct Case {
    std::string text;
    int line;
    std::string word;
  };
  const std::vector<Case> cases{
      {head + r1 + "  - id: r3\n    path: [[0, 0, 0]]\n", 8, "'r3' is not in the instance"},
      {head + r1, 4, "robot 'r2' has no path"},
      {head + r1 + r2 + r2, 11, "second path (first on line 8)"},
      {head + r1 + "  - id: r2\n    path: []\n", 9, "non-empty list"},
      {head + r1 + "  - id: r2\n    path: [[5, 5]]\n", 9, "state 0 must be a list"},
      {head + r1 + "  - id: r2\n    path: [[5, 5, 2], [5, x, 2]]\n", 9, "state 1 y"},
      {head + r1 + "  - id: r2\n    path: [[5, 5, 2], [5, 6, 4]]\n", 9, "heading must be 0..3"},
      {head + r1 + "  - id: r2\n    path: [[5, 5.5, 2]]\n", 9, "must be an integer"},
      {head + r1 + "  - id: r2\n    path:\n      - [5, 5, 2]\n      - 7\n", 11, "state 1"},
      {head + r1 + "  - path: [[5, 5, 2]]\n", 8, "has no 'id'"},
      {head + r1 + "  - id: r2\n    speed: 1\n    path: [[5, 5, 2]]\n", 9, "unknown key 'speed'"},
      {"soc: 4\nmakespan: 3\nrobots:\n" + r1 + r2, 0, "has no 'format'"},
      {"format: fleet_planner/plan/2\nrobots:\n" + r1 + r2, 1, "format must be"},
      {"format: fleet_planner/plan/1\nsoc: 5\nmakespan: 3\nrobots:\n" + r1 + r2, 2,
       "soc is 5 but the paths give 4"},
      {"format: fleet_planner/plan/1\nsoc: 4\nmakespan: 2\nrobots:\n" + r1 + r2, 3, "makespan"},
      {head + r1 + "  - id: r2\n    cost: 2\n    path: [[5, 5, 2], [5, 6, 2]]\n", 9,
       "cost of robot 'r2' is 2"},
      {head + "  - id: r1\n    path: [[0, 0, 0]\n", 7, "YAML syntax error"},
      {head + r1 + r2 + "extra: 1\n", 11, "unknown key 'extra'"},
      {"", 0, "must be a mapping"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    const std::string path = scratchFile("bad_plan.yaml", c.text);
    expectParseError([&] { loadPlan(path, twoRobots()); }, "bad_plan.yaml", c.line, c.word);
  }
  expectParseError([] { loadPlan(scratchPath("no_such_plan.yaml"), twoRobots()); },
                   "no_such_plan.yaml", 0, "cannot open");
}

}  // namespace
}  // namespace fleet_planner
