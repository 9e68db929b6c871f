// Tests of instance_io.h: the benchmark's instance format and YAML scenarios.
#include "fleet_planner/io/instance_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/io/map_io.h"
#include "fleet_planner/io/node_inputs.h"
#include "test_paths.h"

namespace fleet_planner {
namespace {

using test::dataPath;

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
      std::filesystem::path(::testing::TempDir()) / "fleet_planner_instance_io_test";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

std::string scratchFile(const std::string& name, const std::string& content) {
  const std::string path = scratchPath(name);
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

Instance parseText(const std::string& text) {
  std::istringstream in(text);
  return parseBenchmarkInstance(in, "inline.txt");
}

void expectSameRobots(const Instance& a, const Instance& b) {
  ASSERT_EQ(a.robots.size(), b.robots.size());
  for (std::size_t i = 0; i < a.robots.size(); ++i) {
    SCOPED_TRACE("robot " + a.robots[i].id);
    EXPECT_EQ(a.robots[i].id, b.robots[i].id);
    EXPECT_EQ(a.robots[i].footprint, b.robots[i].footprint);
    EXPECT_EQ(a.robots[i].start, b.robots[i].start);
    EXPECT_EQ(a.robots[i].target, b.robots[i].target);
  }
}

TEST(BenchmarkInstanceIo, ReadsTheIdColumn) {
  const std::string path = dataPath("instance_with_ids.txt");
  const Instance instance = loadBenchmarkInstance(path);
  ASSERT_EQ(instance.robots.size(), 3u);
  EXPECT_TRUE(instance.map_file.empty());
  const Robot& circle = instance.robots[0];
  EXPECT_EQ(circle.id, "7");
  EXPECT_EQ(circle.footprint, Footprint::circle(1.5));
  EXPECT_EQ(circle.start, (GridPose{10, 4, 0}));
  EXPECT_EQ(circle.target, (GridPose{30, 4, 2}));
  EXPECT_EQ(circle.source, path + ":1");
  const Robot& block = instance.robots[1];
  EXPECT_EQ(block.id, "9");
  EXPECT_EQ(block.footprint, Footprint::block(-1, -0.5, 2, 0.5));
  EXPECT_EQ(block.footprint.min_y, -0.5);
  EXPECT_EQ(block.footprint.max_x, 2.0);
  EXPECT_EQ(block.start, (GridPose{5, 6, 1}));
  EXPECT_EQ(block.target, (GridPose{8, 9, 3}));
  EXPECT_EQ(instance.robots[2].id, "a");
  EXPECT_EQ(instance.robots[2].source, path + ":3");
}

TEST(BenchmarkInstanceIo, NumbersRobotsWithoutIdColumnFromZero) {
  const std::string path = dataPath("instance_without_ids_crlf.txt");
  const Instance instance = loadBenchmarkInstance(path);
  ASSERT_EQ(instance.robots.size(), 2u);
  EXPECT_EQ(instance.robots[0].id, "0");
  EXPECT_EQ(instance.robots[1].id, "1");
  EXPECT_EQ(instance.robots[1].source, path + ":4");  // blank lines count
  Instance with_ids = loadBenchmarkInstance(dataPath("instance_with_ids.txt"));
  with_ids.robots.resize(2);
  with_ids.robots[0].id = "0";
  with_ids.robots[1].id = "1";
  expectSameRobots(instance, with_ids);
}

TEST(BenchmarkInstanceIo, AcceptsIntegerValuedNumbersAsPositions) {
  const Instance instance = parseText("Circle 0.5 3.0 +4 1e0 2 2 0\n");
  EXPECT_EQ(instance.robots[0].start, (GridPose{3, 4, 1}));
  EXPECT_EQ(instance.robots[0].footprint, Footprint::circle(0.5));
  EXPECT_EQ(instance.robots[0].source, "inline.txt:1");
}

TEST(BenchmarkInstanceIo, RejectsMalformedLines) {
  struct Case {
    std::string text;
    int line;
    std::string word;
  };
  const std::vector<Case> cases{
      {"Circle 1.5abc 1 1 0 2 2 0\n", 1, "'1.5abc'"},
      {"Circle nan 1 1 0 2 2 0\n", 1, "r is not a finite number"},
      {"Circle 1 inf 1 0 2 2 0\n", 1, "sx is not a finite number"},
      {"Circle 1 1 1 0 2 2.5 0\n", 1, "ty must be an integer"},
      {"Circle 1 1 1 4 2 2 0\n", 1, "so must be 0..3"},
      {"Circle 1 1 1 0 2 2 -1\n", 1, "to must be 0..3"},
      {"Circle 1 1 1 0.5 2 2 0\n", 1, "so must be an integer"},
      {"Square 1 1 1 0 2 2 0\n", 1, "unknown robot kind 'Square'"},
      {"circle 1 1 1 0 2 2 0\n", 1, "unknown robot kind"},
      {"Circle 1 1 1 0 2 2\n", 1, "7 fields, expected 8"},
      {"Circle x 1 1 1 0 2 2 0 9\n", 1, "10 fields"},
      {"Block_2D -1 -1 1 1 1 1 0 2 2\n", 1, "10 fields, expected 11"},
      {"Block_2D 3 -1 -1 1 1 1 1 0 2 2 0 5\n", 1, "13 fields"},
      {"Circle -1 1 1 0 2 2 0\n", 1, "invalid footprint"},
      {"Circle 0 1 1 0 2 2 0\n", 1, "radius"},
      {"Block_2D 1 -1 -1 1 1 1 0 2 2 0\n", 1, "invalid footprint"},
      {"Block_2D -1 -1 1 x 1 1 0 2 2 0\n", 1, "max_y"},
      {"Circle a 1 1 1 0 2 2 0\nCircle b 1 1 1 0 2 2 0\nCircle a 1 1 1 0 2 2 0\n", 3,
       "duplicate robot id 'a' (first on line 1)"},
      {"Circle a 1 1 1 0 2 2 0\nCircle 1 1 1 0 2 2 0\n", 2, "lacks the id column"},
      {"Circle 1 1 1 0 2 2 0\nCircle a 1 1 1 0 2 2 0\n", 2, "has the id column"},
      {"\n\nCircle 1 1 1 0 2 2 0\n\nCircle 1 1 1 0 2 z 0\n", 5, "'z'"},
      {"", 0, "no robots"},
      {"  \n\n", 0, "no robots"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    expectParseError([&] { parseText(c.text); }, "inline.txt", c.line, c.word);
  }
  expectParseError([] { loadBenchmarkInstance(dataPath("no_such_instance.txt")); },
                   "no_such_instance.txt", 0, "cannot open");
}

TEST(ScenarioIo, LoadsEveryFootprintType) {
  const std::string path = dataPath("scenario_three_footprints.yaml");
  const Instance instance = loadScenario(path);
  EXPECT_EQ(instance.map_file, dataPath("movingai_5x4_all_chars.map"));
  ASSERT_EQ(instance.robots.size(), 3u);
  EXPECT_EQ(instance.robots[0].id, "r1");
  EXPECT_EQ(instance.robots[0].footprint, Footprint::circle(1.5));
  EXPECT_EQ(instance.robots[0].start, (GridPose{10, 4, 0}));
  EXPECT_EQ(instance.robots[0].target, (GridPose{30, 4, 2}));
  EXPECT_EQ(instance.robots[0].source, path + ":4");
  EXPECT_EQ(instance.robots[1].footprint, Footprint::block(-1.0, -0.5, 2.0, 0.5));
  EXPECT_EQ(instance.robots[1].source, path + ":8");
  const Footprint triangle =
      Footprint::polygon({Eigen::Vector2d(1, 0), Eigen::Vector2d(-1, 1), Eigen::Vector2d(-1, -1)});
  EXPECT_EQ(instance.robots[2].footprint, triangle);
  EXPECT_EQ(instance.robots[2].start, (GridPose{2, 2, 2}));
  EXPECT_EQ(instance.robots[2].target, (GridPose{2, 9, 3}));
  // The map it names loads.
  EXPECT_EQ(loadMovingAiMap(instance.map_file).width(), 5);
}

TEST(ScenarioIo, ScenarioWithoutMapHasEmptyMapFile) {
  const std::string path = scratchFile(
      "no_map.yaml",
      "robots:\n  - {id: a, footprint: {type: circle, radius: 1}, start: [0, 0, 0], target: [1, "
      "1, 1]}\n");
  const Instance instance = loadScenario(path);
  EXPECT_TRUE(instance.map_file.empty());
  ASSERT_EQ(instance.robots.size(), 1u);
  EXPECT_EQ(instance.robots[0].target, (GridPose{1, 1, 1}));
}

TEST(ScenarioIo, ParsesTextWithThePathForMessagesAndTheMapFolder) {
  std::istringstream in(
      "map: ../maps/w.map\n"
      "robots:\n  - {id: a, footprint: {type: circle, radius: 1}, start: [0, 0, 0], target: [1, "
      "1, 1]}\n");
  const Instance instance = parseScenario(in, "scenarios/s.yaml");
  EXPECT_EQ(instance.map_file, "maps/w.map");
  ASSERT_EQ(instance.robots.size(), 1u);
  EXPECT_EQ(instance.robots[0].source, "scenarios/s.yaml:3");
  std::istringstream bad("robots:\n  - {id: a}\n");
  expectParseError([&] { parseScenario(bad, "inline.yaml"); }, "inline.yaml", 2,
                   "has no 'footprint'");
}

TEST(ScenarioIo, WritesTheDocumentedFormat) {
  Instance instance;
  instance.robots.push_back(
      Robot{"r1", Footprint::circle(1.5), GridPose{10, 4, 0}, GridPose{30, 4, 2}, ""});
  instance.robots.push_back(
      Robot{"r 2", Footprint::block(-1, -0.5, 2, 0.5), GridPose{5, 6, 1}, GridPose{8, 9, 3}, ""});
  instance.robots.push_back(Robot{"r3",
                                  Footprint::polygon({Eigen::Vector2d(1, 0), Eigen::Vector2d(-1, 1),
                                                      Eigen::Vector2d(-1, -1.25)}),
                                  GridPose{2, 2, 2}, GridPose{2, 9, 3}, ""});
  EXPECT_EQ(scenarioToYaml(instance, "maps/warehouse.map"),
            "# fleet_planner scenario: start and target are [x, y, heading]; heading 0 = +x, "
            "1 = -x, 2 = +y, 3 = -y\n"
            "map: maps/warehouse.map\n"
            "robots:\n"
            "  - id: r1\n"
            "    footprint: {type: circle, radius: 1.5}\n"
            "    start: [10, 4, 0]\n"
            "    target: [30, 4, 2]\n"
            "  - id: \"r 2\"\n"
            "    footprint: {type: block, min_x: -1, min_y: -0.5, max_x: 2, max_y: 0.5}\n"
            "    start: [5, 6, 1]\n"
            "    target: [8, 9, 3]\n"
            "  - id: r3\n"
            "    footprint: {type: polygon, points: [[1, 0], [-1, 1], [-1, -1.25]]}\n"
            "    start: [2, 2, 2]\n"
            "    target: [2, 9, 3]\n");
  EXPECT_EQ(scenarioToYaml(instance, "").find("map:"), std::string::npos);
}

TEST(ScenarioIo, RoundTripsThroughAFile) {
  Instance instance = loadScenario(dataPath("scenario_three_footprints.yaml"));
  // Awkward ids and numbers that only survive with exact formatting and quoting.
  instance.robots[0].id = "null";
  instance.robots[1].id = "quote\"and\\back slash: #x";
  instance.robots[2].id = "-7";
  instance.robots[0].footprint = Footprint::circle(0.1);
  instance.robots[1].footprint = Footprint::block(-1e-7, -0.30000000000000004, 1.0 / 3.0, 123.456);
  const std::string path = scratchPath("round_trip.yaml");
  saveScenario(instance, path);
  const Instance back = loadScenario(path);
  EXPECT_EQ(back.map_file, instance.map_file);
  expectSameRobots(back, instance);
  // Written again, it is the same text.
  EXPECT_EQ(scenarioToYaml(back, back.map_file), scenarioToYaml(instance, instance.map_file));
}

TEST(ScenarioIo, RefusesToWriteBadInstances) {
  Instance instance = loadScenario(dataPath("scenario_three_footprints.yaml"));
  EXPECT_THROW(saveScenario(instance, "/no_such_dir_fleet_planner/x.yaml"), InvalidInput);
  try {
    saveScenario(instance, "/no_such_dir_fleet_planner/x.yaml");
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("/no_such_dir_fleet_planner/x.yaml"), std::string::npos);
  }
  instance.robots[2].id = "r1";
  EXPECT_THROW(scenarioToYaml(instance, ""), InvalidInput);
  instance.robots[2].id = "";
  EXPECT_THROW(scenarioToYaml(instance, ""), InvalidInput);
  EXPECT_THROW(scenarioToYaml(Instance{}, ""), InvalidInput);
}

TEST(ScenarioIo, RejectsBadScenarios) {
  const std::string ok_robot =
      "  - id: ok\n"
      "    footprint: {type: circle, radius: 1}\n"
      "    start: [0, 0, 0]\n"
      "    target: [1, 1, 1]\n";
  struct Case {
    std::string robot;  // a robot entry at line 6 (after "robots:" and ok_robot)
    int line;
    std::string word;
  };
  const auto robot = [](const std::string& id, const std::string& footprint,
                        const std::string& start, const std::string& target) {
    return "  - id: " + id + "\n    footprint: " + footprint + "\n    start: " + start +
           "\n    target: " + target + "\n";
  };
  const std::string circle = "{type: circle, radius: 1}";
  const std::vector<Case> cases{
      {"  - footprint: " + circle + "\n    start: [0, 0, 0]\n    target: [0, 0, 0]\n", 6,
       "has no 'id'"},
      {robot("\"\"", circle, "[0, 0, 0]", "[0, 0, 0]"), 6, "non-empty string"},
      {robot("", circle, "[0, 0, 0]", "[0, 0, 0]"), 6, "non-empty string"},
      {robot("[a]", circle, "[0, 0, 0]", "[0, 0, 0]"), 6, "non-empty string"},
      {robot("ok", circle, "[0, 0, 0]", "[0, 0, 0]"), 6,
       "duplicate robot id 'ok' (first on line 2)"},
      {robot("b", "{type: square, radius: 1}", "[0, 0, 0]", "[0, 0, 0]"), 7,
       "circle, block or polygon"},
      {robot("b", "{radius: 1}", "[0, 0, 0]", "[0, 0, 0]"), 7, "has no 'type'"},
      {robot("b", "{type: circle, radius: -1}", "[0, 0, 0]", "[0, 0, 0]"), 7, "invalid footprint"},
      {robot("b", "{type: circle, radius: abc}", "[0, 0, 0]", "[0, 0, 0]"), 7, "radius"},
      {robot("b", "{type: circle, radius: .nan}", "[0, 0, 0]", "[0, 0, 0]"), 7, "finite"},
      {robot("b", "{type: circle}", "[0, 0, 0]", "[0, 0, 0]"), 7, "has no 'radius'"},
      {robot("b", "{type: block, min_x: -1, min_y: -1, max_x: 1, max_y: 1, radius: 2}", "[0, 0, 0]",
             "[0, 0, 0]"),
       7, "does not belong to a block"},
      {robot("b", "{type: block, min_x: 1, min_y: -1, max_x: -1, max_y: 1}", "[0, 0, 0]",
             "[0, 0, 0]"),
       7, "invalid footprint"},
      {robot("b", "{type: polygon, points: [[0, 0], [1, 0]]}", "[0, 0, 0]", "[0, 0, 0]"), 7,
       "invalid footprint"},
      {robot("b", "{type: polygon, points: [[0, 0], [1, 0, 2], [0, 1]]}", "[0, 0, 0]", "[0, 0, 0]"),
       7, "point 1 must be a list [x, y]"},
      {robot("b", circle, "[1, 2]", "[0, 0, 0]"), 8, "start must be a list"},
      {robot("b", circle, "[1.5, 2, 0]", "[0, 0, 0]"), 8, "start x must be an integer"},
      {robot("b", circle, "[1, 2, 0]", "[0, 0, 5]"), 9, "target heading must be 0..3"},
      {robot("b", circle, "[1, 2, 0]", "[0, y, 0]"), 9, "target y must be a finite number"},
      {robot("b", circle, "[1, 2, 0]", "[0, 0, 0]") + "    speed: 3\n", 10, "unknown key 'speed'"},
      {robot("b", circle, "[1, 2, 0]", "[0, 0, 0]") + "    start: [1, 1, 1]\n", 10,
       "duplicate key 'start'"},
      {"  - id: b\n    footprint: {type: circle, radius: 1\n", 8, "YAML syntax error"},
  };
  for (const Case& c : cases) {
    const std::string text = "robots:\n" + ok_robot + c.robot;
    SCOPED_TRACE(text);
    const std::string path = scratchFile("bad_scenario.yaml", text);
    expectParseError([&] { loadScenario(path); }, "bad_scenario.yaml", c.line, c.word);
  }
  struct FileCase {
    std::string text;
    int line;
    std::string word;
  };
  const std::vector<FileCase> file_cases{
      {"map: x.map\n", 0, "has no 'robots'"},
      {"robots: []\n", 1, "non-empty list"},
      {"robots: 3\n", 1, "non-empty list"},
      {"robots:\n" + ok_robot + "vehicles: 2\n", 6, "unknown key 'vehicles'"},
      {"map: [a, b]\nrobots:\n" + ok_robot, 1, "map must be a non-empty string"},
      {"", 0, "must be a mapping"},
      {"- 1\n- 2\n", 0, "must be a mapping"},
  };
  for (const FileCase& c : file_cases) {
    SCOPED_TRACE(c.text);
    const std::string path = scratchFile("bad_scenario_file.yaml", c.text);
    expectParseError([&] { loadScenario(path); }, "bad_scenario_file.yaml", c.line, c.word);
  }
  expectParseError([] { loadScenario(dataPath("no_such_scenario.yaml")); }, "no_such_scenario.yaml",
                   0, "cannot open");
}

TEST(InstanceIo, LoadInstanceDispatchesOnTheExtension) {
  EXPECT_EQ(loadInstance(dataPath("scenario_three_footprints.yaml")).robots[2].id, "r3");
  EXPECT_EQ(loadInstance(dataPath("instance_with_ids.txt")).robots[2].id, "a");
  const std::string yml = scratchFile("upper.YML",
                                      "robots: [{id: z, footprint: {type: circle, "
                                      "radius: 1}, start: [0, 0, 0], target: [0, "
                                      "0, 0]}]\n");
  EXPECT_EQ(loadInstance(yml).robots[0].id, "z");
}

TEST(InstanceIo, LoadInstanceReadsAScenarioWhateverItsName) {
  // What `generate --out fleet.scen` writes: a scenario under a pool's kind of name.
  Instance made = loadInstance(dataPath("scenario_three_footprints.yaml"));
  const std::string scen = scratchFile("fleet.scen", scenarioToYaml(made, "grid.map"));
  EXPECT_EQ(loadInstance(scen).robots[2].id, "r3");
  const std::string bare = scratchFile("bare.txt",
                                       "\n  robots: [{id: q, footprint: {type: circle, radius: 1}, start: [0, 0, 0], "
                                       "target: [0, 0, 0]}]\n");
  EXPECT_EQ(loadInstance(bare).robots[0].id, "q");
  // A pool stays a pool, and a bad pool line is still named as one.
  EXPECT_EQ(loadInstance(dataPath("instance_with_ids.txt")).robots[2].id, "a");
  const std::string bad = scratchFile("bad.txt", "Square 0 1 2 3 0 4 5 0\n");
  EXPECT_THROW(loadInstance(bad), ParseError);
}

TEST(SharedBenchmarkIo, EveryMapAndPoolLoadsWithTheReadmeSizes) {
  const std::string root = std::string(FLEET_PLANNER_TEST_DATA) + "/../../../shared/benchmark";
  if (!std::filesystem::exists(root + "/README.md")) GTEST_SKIP() << "no " << root;
  struct Entry {
    std::string name;
    int width;
    int height;
    std::size_t pool;
  };
  // The README's table: map, size (width x height), pool.
  const std::vector<Entry> table{
      {"empty-48-48", 48, 48, 60},    {"maze-128-128-10", 128, 128, 100},
      {"den520d", 256, 257, 140},     {"Berlin_1_256", 256, 256, 140},
      {"Paris_1_256", 256, 256, 140}, {"ost003d", 194, 194, 100},
      {"AR0044SR", 80, 80, 140},      {"AR0203SR", 76, 75, 40},
  };
  for (const Entry& e : table) {
    SCOPED_TRACE(e.name);
    const GridMap map = loadMovingAiMap(root + "/maps/" + e.name + ".map");
    EXPECT_EQ(map.width(), e.width);
    EXPECT_EQ(map.height(), e.height);
    const Instance pool = loadBenchmarkInstance(root + "/instances/" + e.name + "_la.txt");
    EXPECT_EQ(pool.robots.size(), e.pool);
    // With x = column and y = row, every start and target cell is passable.
    for (const Robot& robot : pool.robots) {
      EXPECT_FALSE(map.blocked(robot.start.x, robot.start.y)) << robot.source;
      EXPECT_FALSE(map.blocked(robot.target.x, robot.target.y)) << robot.source;
    }
  }
}

}  // namespace
}  // namespace fleet_planner

namespace fleet_planner {
namespace {

// The node's own inputs (the demo's map, fleet and tasks files) as an instance, and bad ones named.
TEST(NodeInputs, TheDemoFleetAndTasksBecomeAnInstanceOnTheMap) {
  const std::string root = std::string(FLEET_PLANNER_TEST_DATA) + "/../../";
  const GridMap map = loadMap(root + "maps/warehouse.yaml");
  const Instance instance = loadFleetTasks(map, root + "config/demo_fleet.yaml", root + "config/demo_tasks.yaml");
  ASSERT_EQ(instance.robots.size(), 10u);
  EXPECT_EQ(instance.robots[0].id, "amr_4");
  // amr_4: robot_radius 0.35 m on 0.2 m cells; start [4.1, 1.7, 0] is the centre of cell (20, 8).
  EXPECT_NEAR(instance.robots[0].footprint.radius, 1.75, 1e-9);
  EXPECT_EQ(instance.robots[0].start, (GridPose{20, 8, 0}));
  EXPECT_FALSE(instance.robots[0].start_yaw.has_value());
  EXPECT_EQ(instance.robots[0].target.heading, 1);  // yaw pi: -x
}

TEST(NodeInputs, AnyYawIsKeptAndBadTasksAreNamed) {
  const std::string root = std::string(FLEET_PLANNER_TEST_DATA) + "/../../";
  const GridMap map = loadMap(root + "maps/warehouse.yaml");
  const std::string dir = ::testing::TempDir();
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir + name) << text;
    return dir + name;
  };
  const std::string fleet = write("fleet.yaml", "robots:\n  - id: a\n    robot_radius: 0.3\n    footprint_padding: 0.1\n");
  Instance one = loadFleetTasks(map, fleet, write("tasks.yaml", "tasks:\n  - id: a\n    start: [4.1, 1.7, 0.7]\n    goal: [4.1, 4.1, 0.1]\n"));
  ASSERT_TRUE(one.robots[0].start_yaw.has_value());
  EXPECT_NEAR(*one.robots[0].start_yaw, 0.7, 1e-12);
  EXPECT_FALSE(one.robots[0].target_yaw.has_value());  // within heading_tolerance
  EXPECT_NEAR(one.robots[0].footprint.radius, 2.0, 1e-9);  // (0.3 + 0.1) / 0.2
  try {
    loadFleetTasks(map, fleet, write("bad.yaml", "tasks:\n  - id: a\n    start: [4.1, 1.7, 0]\n    goal: [4.1, 4.1, 0]\n  - id: ghost\n    start: [1, 1, 0]\n    goal: [2, 2, 0]\n"));
    FAIL() << "a task for a robot the fleet lacks was accepted";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 5) << e.what();
    EXPECT_NE(std::string(e.what()).find("'ghost'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fleet_planner
