// Tests of map_io.h: MovingAI maps and ROS map_server maps (YAML + PGM).
#include "fleet_planner/io/map_io.h"
#include "fleet_planner/runtime/resource_limits.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "fleet_planner/runtime/errors.h"
#include "test_paths.h"

namespace fleet_planner {
namespace {

using test::dataPath;
using test::fuzzRegressionPath;

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

/// The map as text, top row (highest y) first: '@' blocked, '.' free.
std::vector<std::string> picture(const GridMap& map) {
  std::vector<std::string> rows;
  for (int y = map.height() - 1; y >= 0; --y) {
    std::string row;
    for (int x = 0; x < map.width(); ++x) row += map.blocked(x, y) ? '@' : '.';
    rows.push_back(row);
  }
  return rows;
}

/// Writes `content` to a file `name` in a scratch folder and returns its path.
std::string scratchFile(const std::string& name, const std::string& content) {
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / "fleet_planner_map_io_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

GridMap parseText(const std::string& text) {
  std::istringstream in(text);
  return parseMovingAiMap(in, "inline.map");
}

TEST(MovingAiMapIo, LoadsEveryCellAsWritten) {
  const std::string path = dataPath("movingai_5x4_all_chars.map");
  const GridMap map = loadMovingAiMap(path);
  ASSERT_EQ(map.width(), 5);
  ASSERT_EQ(map.height(), 4);
  EXPECT_EQ(map.resolution(), 1.0);
  EXPECT_EQ(map.origin().x, 0.0);
  EXPECT_EQ(map.origin().y, 0.0);
  EXPECT_EQ(map.source(), path);
  // Row y of the file is grid row y; '.', 'G', 'S' free; '@', 'O', 'T', 'W' blocked.
  const std::vector<std::string> rows{".@..T", "G.O.S", "..W..", "@...."};
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 5; ++x) {
      const bool expected = rows[y][x] != '.' && rows[y][x] != 'G' && rows[y][x] != 'S';
      EXPECT_EQ(map.blocked(x, y), expected) << "cell " << x << "," << y;
    }
  }
  EXPECT_TRUE(map.blocked(1, 0));
  EXPECT_TRUE(map.blocked(0, 3));
  EXPECT_FALSE(map.blocked(0, 1));
  EXPECT_EQ(map.numFreeCells(), 15);
}

TEST(MovingAiMapIo, AcceptsCrlfAndWidthBeforeHeight) {
  const GridMap map = loadMovingAiMap(dataPath("movingai_crlf_width_first.map"));
  ASSERT_EQ(map.width(), 3);
  ASSERT_EQ(map.height(), 2);
  EXPECT_TRUE(map.blocked(1, 0));
  EXPECT_TRUE(map.blocked(2, 1));
  EXPECT_FALSE(map.blocked(0, 1));
  EXPECT_FALSE(map.blocked(2, 0));
}

TEST(MovingAiMapIo, AcceptsBlankLinesAfterTheLastRow) {
  const GridMap map = parseText("type octile\nheight 1\nwidth 2\nmap\n.@\n\n  \n");
  EXPECT_EQ(map.width(), 2);
  EXPECT_TRUE(map.blocked(1, 0));
  EXPECT_EQ(map.source(), "inline.map");
}

TEST(MovingAiMapIo, UnknownCharacterNamesLineAndColumn) {
  expectParseError([] { loadMovingAiMap(dataPath("bad_map_unknown_char.map")); },
                   "bad_map_unknown_char.map", 6, "unknown character 'x' at column 3");
}

TEST(MovingAiMapIo, MissingFileIsAParseError) {
  expectParseError([] { loadMovingAiMap(dataPath("no_such.map")); }, "no_such.map", 0,
                   "cannot open");
}

TEST(MovingAiMapIo, RejectsMalformedInput) {
  struct Case {
    std::string text;
    int line;
    std::string word;
  };
  const std::string head = "type octile\nheight 2\nwidth 3\nmap\n";
  const std::vector<Case> cases{
      {head + "...\n..\n", 6, "2 characters, expected 3"},
      {head + "....\n...\n", 5, "4 characters"},
      {head + "...\n", 5, "1 of 2 map rows"},
      {head + "...\n...\n...\n", 7, "extra line"},
      {head + "...\n. .\n", 6, "unknown character ' ' at column 2"},
      {"type octile\nheight abc\nwidth 3\nmap\n", 2, "height must be an integer"},
      {"type octile\nheight 2\nwidth 0\nmap\n", 3, "width must be an integer"},
      {"type octile\nheight -2\nwidth 3\nmap\n", 2, "height"},
      {"type octile\nheight 2.5\nwidth 3\nmap\n", 2, "height"},
      {"type octile\nheight 100001\nwidth 3\nmap\n", 2, "100000"},
      {"type octile\nheight 100000\nwidth 100000\nmap\n", 0, "2^28"},
      {"height 2\nwidth 3\nmap\n", 1, "type"},
      {"type octile\nheight 2\nheight 2\nmap\n", 3, "repeated 'height'"},
      {"type octile\nheight 2\nwidth 3\nrows\n", 4, "'map'"},
      {"type octile\nheight 2\nsize 3\nmap\n", 3, "'width W'"},
      {"type octile\nheight 2\n", 0, "file ends"},
      {"", 0, "file ends"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    expectParseError([&] { parseText(c.text); }, "inline.map", c.line, c.word);
  }
}

TEST(MovingAiMapIo, HeaderClaimingAHugeMapWithoutRowsIsAnErrorNotAnAllocation) {
  // Found by fuzz/movingai_map_fuzz.cpp: the reader allocated the 2^28 cells the header claims
  // (256 MB) before reading a row. With max_map_cells above the claim, the reader itself must not
  // allocate ahead of the rows; with the default limit, the header is refused first.
  ResourceLimits roomy;
  roomy.max_map_cells = 1'000'000'000;
  const std::string path = fuzzRegressionPath("movingai_map/header_claims_16384x16384_cells_without_rows");
  expectParseError([&] { loadMovingAiMap(path, roomy); }, "header_claims_16384x16384_cells_without_rows", 4,
                   "file ends after 0 of 16384 map rows");
  expectParseError(
      [&] {
        std::istringstream in("type octile\nheight 16384\nwidth 16384\nmap\n...\n");
        parseMovingAiMap(in, "inline.map", roomy);
      },
      "inline.map", 5, "map row 0 has 3 characters, expected 16384");
  EXPECT_THROW(loadMovingAiMap(path), ResourceLimitError);
}

TEST(MapServerMapIo, LoadsP2WithTheImageTopRowAtTheHighestY) {
  const GridMap map = loadMapServerMap(dataPath("map_server_p2.yaml"));
  ASSERT_EQ(map.width(), 4);
  ASSERT_EQ(map.height(), 3);
  EXPECT_EQ(map.resolution(), 0.5);
  EXPECT_EQ(map.source(), dataPath("map_server_p2.yaml"));
  // Image rows (top first): 0 254 254 205 / 254 254 0 254 / 254 205 254 254; 205 is unknown.
  EXPECT_EQ(picture(map), (std::vector<std::string>{"@..@", "..@.", ".@.."}));
  EXPECT_TRUE(map.blocked(0, 2));   // image row 0, column 0 (value 0)
  EXPECT_FALSE(map.blocked(0, 0));  // image row 2, column 0 (value 254)
  EXPECT_TRUE(map.blocked(2, 1));
}

TEST(MapServerMapIo, UnknownCellsAreFreeOnlyWhenAsked) {
  MapServerOptions options;
  options.unknown_is_free = true;
  const GridMap map = loadMapServerMap(dataPath("map_server_p2.yaml"), options);
  EXPECT_EQ(picture(map), (std::vector<std::string>{"@...", "..@.", "...."}));
}

TEST(MapServerMapIo, NegateTreatsDarkPixelsAsFree) {
  const GridMap map = loadMapServerMap(dataPath("map_server_p2_negate.yaml"));
  // p = v / 255: 0 -> free, 254 -> occupied, 205 (p = 0.80) -> occupied.
  EXPECT_EQ(picture(map), (std::vector<std::string>{".@@@", "@@.@", "@@@@"}));
}

TEST(MapServerMapIo, UsesTheThresholdsOfTheYaml) {
  MapServerOptions options;
  options.unknown_is_free = true;
  // occupied_thresh 0.1: the 205 gray (p = 0.196) is occupied, not unknown.
  const GridMap map = loadMapServerMap(dataPath("map_server_p2_low_thresholds.yaml"), options);
  EXPECT_EQ(picture(map), (std::vector<std::string>{"@..@", "..@.", ".@.."}));
}

TEST(MapServerMapIo, UsesTheFreeThresholdOfTheYaml) {
  // free_thresh 0.3: the 205 gray (p = 0.196) is free even though unknown cells are blocked.
  const GridMap map = loadMapServerMap(dataPath("map_server_p2_high_free_thresh.yaml"));
  EXPECT_EQ(picture(map), (std::vector<std::string>{"@...", "..@.", "...."}));
}

TEST(MapServerMapIo, ScaleModeMatchesTrinaryOnABinaryGrid) {
  EXPECT_EQ(picture(loadMapServerMap(dataPath("map_server_p2_scale.yaml"))),
            (std::vector<std::string>{"@..@", "..@.", ".@.."}));
  MapServerOptions options;
  options.unknown_is_free = true;
  EXPECT_EQ(picture(loadMapServerMap(dataPath("map_server_p2_scale.yaml"), options)),
            (std::vector<std::string>{"@...", "..@.", "...."}));
}

TEST(MapServerMapIo, RawModeReadsPercentages) {
  // Pixels (top row first): 0 100 255 / 50 101 1. >100 is unknown; 50 % lies between the
  // thresholds, so it is unknown too.
  EXPECT_EQ(picture(loadMapServerMap(dataPath("map_server_raw.yaml"))),
            (std::vector<std::string>{".@@", "@@."}));
  MapServerOptions options;
  options.unknown_is_free = true;
  EXPECT_EQ(picture(loadMapServerMap(dataPath("map_server_raw.yaml"), options)),
            (std::vector<std::string>{".@.", "..."}));
}

TEST(MapServerMapIo, LoadsP5WithResolutionAndOrigin) {
  const GridMap map = loadMapServerMap(dataPath("map_server_p5.yaml"));
  ASSERT_EQ(map.width(), 3);
  ASSERT_EQ(map.height(), 2);
  EXPECT_EQ(picture(map), (std::vector<std::string>{"@.@", ".@."}));
  EXPECT_DOUBLE_EQ(map.resolution(), 0.05);
  EXPECT_DOUBLE_EQ(map.origin().x, -1.5);
  EXPECT_DOUBLE_EQ(map.origin().y, 2.0);
  EXPECT_DOUBLE_EQ(map.origin().yaw, 0.25);
}

TEST(MapServerMapIo, LoadsSixteenBitP5) {
  // Pixels 255 65535 / 45875 65000 (big-endian): occupied, free / unknown (p = 0.3), free.
  EXPECT_EQ(picture(loadMapServerMap(dataPath("map_server_p5_16bit.yaml"))),
            (std::vector<std::string>{"@.", "@."}));
  MapServerOptions options;
  options.unknown_is_free = true;
  EXPECT_EQ(picture(loadMapServerMap(dataPath("map_server_p5_16bit.yaml"), options)),
            (std::vector<std::string>{"@.", ".."}));
}

TEST(MapServerMapIo, LoadMapDispatchesOnTheExtension) {
  EXPECT_EQ(loadMap(dataPath("map_server_p2.yaml")).width(), 4);
  EXPECT_EQ(loadMap(dataPath("movingai_5x4_all_chars.map")).width(), 5);
  // The CLI's defaults (backward moves) follow the same rule.
  EXPECT_TRUE(isMapServerMapPath("maps/warehouse.yaml"));
  EXPECT_TRUE(isMapServerMapPath("/x/HOUSE.YML"));
  EXPECT_FALSE(isMapServerMapPath("maze-128-128-10.map"));
  EXPECT_FALSE(isMapServerMapPath("yaml"));
}

TEST(MapServerMapIo, RejectsBadImages) {
  expectParseError([] { loadMapServerMap(dataPath("bad_map_server_png.yaml")); }, "not_a_pgm.png",
                   0, "only PGM images are supported");
  expectParseError([] { loadMapServerMap(dataPath("bad_map_server_truncated_pgm.yaml")); },
                   "bad_pgm_truncated_p5.pgm", 0, "truncated");
  expectParseError([] { loadMapServerMap(dataPath("bad_map_server_missing_image.yaml")); },
                   "bad_map_server_missing_image.yaml", 3, "no_such_image.pgm");

  struct Case {
    std::string name;
    std::string pgm;
    int line;
    std::string word;
  };
  const std::vector<Case> cases{
      {"p2_above_maxval.pgm", "P2\n2 2\n15\n0 15\n16 0\n", 5, "pixel (column 0, row 1)"},
      {"p2_above_maxval_max.pgm", "P2\n2 1\n255\n0 256\n", 4, "must be in [0, 255]"},
      {"p2_truncated.pgm", "P2\n2 2\n255\n0 0\n0\n", 0, "truncated: found 3 of 4"},
      {"p2_extra_values.pgm", "P2\n2 1\n255\n0 0 0\n", 4, "extra data"},
      {"p2_letter.pgm", "P2\n2 1\n255\n0 x\n", 4, "'x'"},
      {"p2_no_height.pgm", "P2\n# only a width\n2\n", 0, "file ends before the image height"},
      {"p2_bad_maxval.pgm", "P2\n2 1\n70000\n0 0\n", 3, "maxval"},
      {"p2_zero_width.pgm", "P2\n0 1\n255\n", 2, "image width"},
      {"p5_extra_bytes.pgm", std::string("P5\n1 1\n255\n") + "ab", 0, "extra data"},
      {"p5_comment_then_pixels.pgm", "P5\n1 1\n255# c\n\x07", 4,
       "expected a whitespace byte between the header and the pixels, found '\\x07'"},
      {"p6_color.pgm", "P6\n1 1\n255\nabc", 0, "only PGM images are supported"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string image = scratchFile(c.name, c.pgm);
    const std::string yaml =
        scratchFile(c.name + ".yaml", "image: " + c.name + "\nresolution: 1\norigin: [0, 0, 0]\n");
    expectParseError([&] { loadMapServerMap(yaml); }, c.name, c.line, c.word);
  }
}

TEST(MapServerMapIo, PgmHeaderClaimingAHugeImageIsAnErrorNotAnAllocation) {
  // Found by fuzz/map_server_map_fuzz.cpp: the PGM reader allocated the pixels its header claims
  // (up to 512 MB for 2^28 pixels) before reading any. The fuzz inputs are "<YAML>\0<PGM>"; the
  // PGM half is loaded here through a good YAML file.
  struct Case {
    std::string regression;
    std::string word;
  };
  const std::vector<Case> cases{
      {"p5_header_claims_25254x2502_pixels_with_4_bytes",
       "truncated: expected 63185508 bytes of pixels, found 4"},
      {"p2_header_claims_16384x16384_pixels_with_2_values",
       "truncated: found 2 of 268435456 pixel values"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.regression);
    std::ifstream in(fuzzRegressionPath("map_server_map/" + c.regression), std::ios::binary);
    const std::string input((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_NE(input.find('\0'), std::string::npos);
    scratchFile(c.regression + ".pgm", input.substr(input.find('\0') + 1));
    const std::string yaml = scratchFile(c.regression + ".yaml", "image: " + c.regression +
                                                                     ".pgm\nresolution: 1\n"
                                                                     "origin: [0, 0, 0]\n");
    MapServerOptions roomy;  // above the claim: the reader itself must not allocate ahead of the data
    roomy.limits.max_map_cells = 1'000'000'000;
    expectParseError([&] { loadMapServerMap(yaml, roomy); }, c.regression + ".pgm", 0, c.word);
    EXPECT_THROW(loadMapServerMap(yaml), ResourceLimitError);  // the default limit refuses the header
  }
}

TEST(MapServerMapIo, P5CommentsBeforeTheRasterAreSkipped) {
  // netpbm: a comment may end the header; the whitespace byte that delimits the raster follows
  // the newline that ends the comment.
  const std::string image =
      scratchFile("p5_comment.pgm", std::string("P5\n2 1\n255# c\n\n\xff") + '\0');
  const std::string yaml =
      scratchFile("p5_comment.yaml", "image: " + image + "\nresolution: 1\norigin: [0, 0, 0]\n");
  EXPECT_EQ(picture(loadMapServerMap(yaml)), (std::vector<std::string>{".@"}));
}

TEST(MapServerMapIo, P2CommentsAndAbsoluteImagePathsWork) {
  const std::string image = scratchFile("commented.pgm", "P2 # magic\n# c\n2 # w\n1\n9\n9 0\n");
  const std::string yaml = scratchFile("absolute_image.yaml",
                                       "image: " + image + "\nresolution: 1\norigin: [0, 0, 0]\n");
  EXPECT_EQ(picture(loadMapServerMap(yaml)), (std::vector<std::string>{".@"}));
}

TEST(MapServerMapIo, RejectsBadYaml) {
  struct Case {
    std::string extra;  // lines 4.. of the YAML, after image, resolution and origin
    std::string resolution;
    std::string origin;
    int line;
    std::string word;
  };
  const std::string image = dataPath("map_server_p2.pgm");
  const std::vector<Case> cases{
      {"", "abc", "[0, 0, 0]", 2, "resolution must be a finite number"},
      {"", ".nan", "[0, 0, 0]", 2, "resolution"},
      {"", "0", "[0, 0, 0]", 2, "positive"},
      {"", "-0.5", "[0, 0, 0]", 2, "positive"},
      {"", "1", "[0, 0]", 3, "origin must be a list"},
      {"", "1", "[0, nope, 0]", 3, "origin y"},
      {"", "1", "[0, 0, .inf]", 3, "origin yaw"},
      {"occupied_thresh: 1.5\n", "1", "[0, 0, 0]", 4, "occupied_thresh must be in [0, 1]"},
      {"free_thresh: -0.1\n", "1", "[0, 0, 0]", 4, "free_thresh must be in [0, 1]"},
      {"free_thresh: 0.7\n", "1", "[0, 0, 0]", 4, "must be below occupied_thresh"},
      {"occupied_thresh: abc\n", "1", "[0, 0, 0]", 4, "occupied_thresh"},
      {"negate: 2\n", "1", "[0, 0, 0]", 4, "negate must be 0 or 1"},
      {"mode: fancy\n", "1", "[0, 0, 0]", 4, "mode must be trinary, scale or raw"},
      {"colour: red\n", "1", "[0, 0, 0]", 4, "unknown key 'colour'"},
      {"resolution: 2\n", "1", "[0, 0, 0]", 4, "duplicate key 'resolution'"},
      {"origin: [0, 0\n", "1", "[0, 0, 0]", 5, "YAML syntax error"},
  };
  for (const Case& c : cases) {
    const std::string text = "image: " + image + "\nresolution: " + c.resolution +
                             "\norigin: " + c.origin + "\n" + c.extra;
    SCOPED_TRACE(text);
    const std::string yaml = scratchFile("bad_map_server.yaml", text);
    expectParseError([&] { loadMapServerMap(yaml); }, "bad_map_server.yaml", c.line, c.word);
  }
  const std::string no_resolution =
      scratchFile("no_resolution.yaml", "image: " + image + "\norigin: [0, 0, 0]\n");
  expectParseError([&] { loadMapServerMap(no_resolution); }, "no_resolution.yaml", 0,
                   "has no 'resolution'");
  const std::string no_image = scratchFile("no_image.yaml", "resolution: 1\norigin: [0, 0, 0]\n");
  expectParseError([&] { loadMapServerMap(no_image); }, "no_image.yaml", 0, "has no 'image'");
  const std::string empty = scratchFile("empty_map.yaml", "");
  expectParseError([&] { loadMapServerMap(empty); }, "empty_map.yaml", 0, "must be a mapping");
  expectParseError([] { loadMapServerMap(dataPath("no_such_map.yaml")); }, "no_such_map.yaml", 0,
                   "cannot open");
}

}  // namespace
}  // namespace fleet_planner
