#include "evaluator/formats/map/map_server_format.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

#include "evaluator/formats/map/map_server_pixels.h"
#include "tests/evaluator/formats/map/map_test_helpers.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using map_test::InputErrorOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;

/// A map_server YAML for `image` with round thresholds (free 0.2, occupied 0.7) so that expected
/// cell values can be worked out by hand.
std::string Yaml(const std::string& image, const std::string& extra = "", const std::string& negate = "0") {
  return "image: " + image + "\nresolution: 0.1\norigin: [1.5, -2.0, 0.25]\nnegate: " + negate +
         "\noccupied_thresh: 0.7\nfree_thresh: 0.2\n" + extra;
}

/// One grid row of a map read from a one-row image.
std::vector<float> ReadRow(const testing::TempDir& dir, const std::string& yaml) {
  testing::WriteFile(dir / "m.yaml", yaml);
  return ReadMapServer(dir / "m.yaml").cells;
}

// Grey levels used below, with occ = (255 - v) / 255:
//   0 -> 1.0, 76 -> 0.702, 102 -> 0.6, 153 -> 0.4, 205 -> 0.196, 230 -> 0.098, 255 -> 0.
const std::vector<std::uint8_t> kGreys = {0, 76, 102, 153, 205, 230, 255};

TEST(MapServerFormatTest, TrinaryUsesStrictThresholds) {
  testing::TempDir dir;
  testing::WriteFile(dir / "g.pgm", map_test::Pgm(7, 1, kGreys));
  EXPECT_THAT(ReadRow(dir, Yaml("g.pgm")),
              ::testing::ElementsAre(1.0f, 1.0f, OccupancyGrid::kUnknown, OccupancyGrid::kUnknown, 0.0f, 0.0f, 0.0f));
  // occ == occupied_thresh is not occupied and occ == free_thresh is not free: 102 -> occ 0.6, 153 -> occ 0.4.
  testing::WriteFile(dir / "e.pgm", map_test::Pgm(4, 1, {101, 102, 153, 154}));
  testing::WriteFile(dir / "m.yaml",
                     "image: e.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: 0\n"
                     "occupied_thresh: 0.6\nfree_thresh: 0.4\n");
  EXPECT_THAT(ReadMapServer(dir / "m.yaml").cells,
              ::testing::ElementsAre(1.0f, OccupancyGrid::kUnknown, OccupancyGrid::kUnknown, 0.0f));
}

TEST(MapServerFormatTest, GeometryComesFromTheYaml) {
  testing::TempDir dir;
  testing::WriteFile(dir / "g.pgm", map_test::Pgm(2, 3, std::vector<std::uint8_t>(6, 254)));
  testing::WriteFile(dir / "m.yaml", Yaml("g.pgm"));
  const OccupancyGrid grid = ReadMapServer(dir / "m.yaml");
  EXPECT_EQ(grid.width, 2);
  EXPECT_EQ(grid.height, 3);
  EXPECT_DOUBLE_EQ(grid.resolution_m, 0.1);
  EXPECT_DOUBLE_EQ(grid.origin.x_m, 1.5);
  EXPECT_DOUBLE_EQ(grid.origin.y_m, -2.0);
  EXPECT_DOUBLE_EQ(grid.origin.yaw_rad, 0.25);
}

TEST(MapServerFormatTest, NegateSwapsBlackAndWhite) {
  testing::TempDir dir;
  testing::WriteFile(dir / "g.pgm", map_test::Pgm(7, 1, kGreys));
  // negate: average = 255 - v, so occ = v / 255: 0 -> free, 76 -> 0.298, 102 -> 0.4, 153 -> 0.6 (unknown),
  // 205 -> 0.804 and above -> occupied.
  EXPECT_THAT(ReadRow(dir, Yaml("g.pgm", "", "1")),
              ::testing::ElementsAre(0.0f, OccupancyGrid::kUnknown, OccupancyGrid::kUnknown, OccupancyGrid::kUnknown,
                                     1.0f, 1.0f, 1.0f));
}

TEST(MapServerFormatTest, ScaleModeGivesNinetyNineTimesTheRatio) {
  testing::TempDir dir;
  testing::WriteFile(dir / "g.pgm", map_test::Pgm(7, 1, kGreys));
  // 102: ratio (0.6 - 0.2) / 0.5 = 0.8 -> 79.2 -> 79;  153: ratio 0.4 -> 39.6 -> 39 (truncated).
  // 205: occ 0.196 < 0.2 -> free.  A grey image has no alpha, so nothing in between is unknown.
  EXPECT_THAT(ReadRow(dir, Yaml("g.pgm", "mode: scale\n")),
              ::testing::ElementsAre(1.0f, 1.0f, 0.79f, 0.39f, 0.0f, 0.0f, 0.0f));
}

TEST(MapServerFormatTest, RawModeKeepsValuesAndRejectsMeaninglessOnes) {
  testing::TempDir dir;
  testing::WriteFile(dir / "r.pgm", map_test::Pgm(5, 1, {0, 37, 100, 255, 1}));
  EXPECT_THAT(ReadRow(dir, Yaml("r.pgm", "mode: raw\n")),
              ::testing::ElementsAre(0.0f, 0.37f, 1.0f, OccupancyGrid::kUnknown, 0.01f));
  // negate applies before raw: 255 - 218 = 37.
  testing::WriteFile(dir / "n.pgm", map_test::Pgm(2, 1, {218, 0}));
  EXPECT_THAT(ReadRow(dir, Yaml("n.pgm", "mode: raw\n", "1")), ::testing::ElementsAre(0.37f, OccupancyGrid::kUnknown));

  testing::WriteFile(dir / "bad.pgm", map_test::Pgm(3, 1, {0, 10, 150}));
  testing::WriteFile(dir / "m.yaml", Yaml("bad.pgm", "mode: raw\n"));
  const std::string message = InputErrorOf([&] { ReadMapServer(dir / "m.yaml"); });
  EXPECT_THAT(message, HasSubstr("bad.pgm"));
  EXPECT_THAT(message, HasSubstr("row 0, column 2"));
  EXPECT_THAT(message, HasSubstr("value 150"));
}

TEST(MapServerFormatTest, ColourIsAveragedOverChannels) {
  testing::TempDir dir;
  // (30, 60, 90): average 60 -> occ 0.765 -> occupied.  (255, 0, 0): 85 -> occ 0.667 -> unknown.
  // (255, 255, 204): 238 -> occ 0.067 -> free.
  map_test::WriteImage(dir / "c.png",
                       map_test::RgbRow({cv::Vec3b(30, 60, 90), cv::Vec3b(255, 0, 0), cv::Vec3b(255, 255, 204)}));
  EXPECT_THAT(ReadRow(dir, Yaml("c.png")), ::testing::ElementsAre(1.0f, OccupancyGrid::kUnknown, 0.0f));
  // raw: (10, 20, 31) averages to 20.33, truncated to 20.
  map_test::WriteImage(dir / "r.png", map_test::RgbRow({cv::Vec3b(10, 20, 31)}));
  EXPECT_THAT(ReadRow(dir, Yaml("r.png", "mode: raw\n")), ::testing::ElementsAre(0.2f));
}

TEST(MapServerFormatTest, AlphaMarksUnknownInScaleModeAndIsAveragedInTrinary) {
  testing::TempDir dir;
  map_test::WriteImage(dir / "a.png", map_test::RgbaRow({cv::Vec4b(153, 153, 153, 0), cv::Vec4b(153, 153, 153, 255),
                                                         cv::Vec4b(255, 255, 255, 0), cv::Vec4b(0, 0, 0, 0)}));
  // Scale: alpha left out of the average; a transparent in-between pixel is unknown, a
  // transparent free or occupied pixel keeps its value.
  EXPECT_THAT(ReadRow(dir, Yaml("a.png", "mode: scale\n")),
              ::testing::ElementsAre(OccupancyGrid::kUnknown, 0.39f, 0.0f, 1.0f));
  // Trinary: alpha is averaged in. (153*3 + 0) / 4 = 114.75 -> occ 0.55 -> unknown;
  // (153*3 + 255) / 4 = 178.5 -> occ 0.3 -> unknown; (255*3 + 0) / 4 = 191.25 -> occ 0.25 -> unknown;
  // 0 -> occupied.
  EXPECT_THAT(ReadRow(dir, Yaml("a.png")),
              ::testing::ElementsAre(OccupancyGrid::kUnknown, OccupancyGrid::kUnknown, OccupancyGrid::kUnknown, 1.0f));
}

TEST(MapServerFormatTest, RgbScaleModeTakesAlphaFromBlueLikeMapServer) {
  const MapServerMetadata metadata{"x.png", 1, 0.1, {}, false, 0.7, 0.2, MapServerMode::kScale};
  // Both average 100 (occ 0.608, ratio 0.816 -> 80); map_server reads the last byte as alpha.
  const std::uint8_t blue_zero[] = {200, 100, 0};
  const std::uint8_t blue_set[] = {0, 200, 100};
  EXPECT_EQ(MapServerPixelValue(blue_zero, 3, metadata), kMapServerUnknownByte);
  EXPECT_EQ(MapServerPixelValue(blue_set, 3, metadata), 80);
}

TEST(MapServerFormatTest, MissingImageNamesTheYamlAndTheImage) {
  testing::TempDir dir;
  testing::WriteFile(dir / "site.yaml", Yaml("gone.pgm"));
  const std::string message = InputErrorOf([&] { ReadMapServer(dir / "site.yaml"); });
  EXPECT_THAT(message, StartsWith((dir / "site.yaml").string() + ":1: field 'image'"));
  EXPECT_THAT(message, HasSubstr((dir / "gone.pgm").string()));
}

TEST(MapServerFormatTest, BadImagesAreInputErrors) {
  testing::TempDir dir;
  testing::WriteFile(dir / "text.pgm", "not an image");
  testing::WriteFile(dir / "m.yaml", Yaml("text.pgm"));
  EXPECT_THAT(InputErrorOf([&] { ReadMapServer(dir / "m.yaml"); }), HasSubstr("text.pgm"));

  testing::WriteFile(dir / "empty.pgm", "");
  testing::WriteFile(dir / "m.yaml", Yaml("empty.pgm"));
  EXPECT_THAT(InputErrorOf([&] { ReadMapServer(dir / "m.yaml"); }), HasSubstr("empty file"));

  const std::string full = map_test::Pgm(10, 10, std::vector<std::uint8_t>(100, 205));
  testing::WriteFile(dir / "cut.pgm", full.substr(0, full.size() - 1));
  testing::WriteFile(dir / "m.yaml", Yaml("cut.pgm"));
  EXPECT_THAT(InputErrorOf([&] { ReadMapServer(dir / "m.yaml"); }), HasSubstr("truncated"));

  EXPECT_THAT(InputErrorOf([&] { ReadMapServer(dir / "none.yaml"); }), HasSubstr("none.yaml"));
}

TEST(MapServerFormatTest, MapWithoutKnownCellsIsStillReadable) {
  testing::TempDir dir;
  // 128: occ 0.498, between the thresholds 0.2 and 0.7.
  testing::WriteFile(dir / "u.pgm", map_test::Pgm(3, 2, std::vector<std::uint8_t>(6, 128)));
  testing::WriteFile(dir / "m.yaml", Yaml("u.pgm"));
  const OccupancyGrid grid = ReadMapServer(dir / "m.yaml");
  EXPECT_EQ(std::count(grid.cells.begin(), grid.cells.end(), OccupancyGrid::kUnknown), 6);
}

// ---- writing ----

TEST(MapServerFormatTest, TrinaryWriteUsesMapSaverLevelsAndLayout) {
  testing::TempDir dir;
  OccupancyGrid grid(6, 2, 0.07, GridOrigin{-48.02000045776367, -52.9900016784668, 0.0});
  // map_saver on v = round(100 p): v >= 65 -> 0, 0 <= v <= 25 -> 254, else 205.
  const std::vector<float> row0 = {0.0f, 0.25f, 0.26f, 0.644f, 0.65f, 1.0f};
  for (int col = 0; col < 6; ++col) grid.at(0, col) = row0[col];
  WriteMapServer(grid, dir / "out.yaml");

  const std::string pgm = map_test::ReadAll(dir / "out.pgm");
  ASSERT_THAT(pgm, StartsWith("P5\n# CREATOR: "));
  const std::string pixels = pgm.substr(pgm.size() - 12);
  EXPECT_EQ(pgm.substr(pgm.size() - 12 - 9, 9), "\n6 2\n255\n");
  const std::vector<int> expected = {254, 254, 205, 205, 0, 0, 205, 205, 205, 205, 205, 205};
  for (int i = 0; i < 12; ++i) EXPECT_EQ(static_cast<unsigned char>(pixels[i]), expected[i]) << "pixel " << i;

  const std::string yaml = map_test::ReadAll(dir / "out.yaml");
  EXPECT_EQ(yaml,
            "image: out.pgm\nresolution: 0.07\norigin: [-48.02000045776367, -52.9900016784668, 0]\n"
            "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n\n");
}

TEST(MapServerFormatTest, TrinaryRoundTripKeepsCellsAndGeometry) {
  testing::TempDir dir;
  OccupancyGrid grid(5, 4, 0.05, GridOrigin{-40.0, -52.0, 0.3});
  for (std::size_t i = 0; i < grid.cells.size(); ++i)
    grid.cells[i] = (i % 3 == 0) ? OccupancyGrid::kUnknown : (i % 3 == 1 ? 0.0f : 1.0f);
  WriteMapServer(grid, dir / "rt.yaml");
  const OccupancyGrid back = ReadMapServer(dir / "rt.yaml");
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 4);
  EXPECT_EQ(back.cells, grid.cells);
  EXPECT_EQ(back.resolution_m, grid.resolution_m);
  EXPECT_EQ(back.origin.x_m, grid.origin.x_m);
  EXPECT_EQ(back.origin.y_m, grid.origin.y_m);
  EXPECT_EQ(back.origin.yaw_rad, grid.origin.yaw_rad);
}

// What the worker scores instead of reading map.yaml again: exactly what ReadMapServer reads, every mode.
TEST(MapServerFormatTest, WriteAndReadBackGivesWhatReadMapServerReads) {
  testing::TempDir dir;
  OccupancyGrid grid(7, 5, 0.05, GridOrigin{-1.25, 3.5, 0.0});
  for (std::size_t i = 0; i < grid.cells.size(); ++i) {
    grid.cells[i] = i % 5 == 0 ? OccupancyGrid::kUnknown : static_cast<float>(i % 11) / 10.0f;
  }
  MapWriteOptions png;
  png.trinary_png = true;
  MapWriteOptions scale;
  scale.mode = MapWriteOptions::Mode::kScale;
  int written = 0;
  for (const MapWriteOptions& options : {MapWriteOptions{}, png, scale}) {
    const std::string yaml = "map" + std::to_string(written++) + ".yaml";
    const OccupancyGrid back = WriteMapServerAndReadBack(grid, dir / yaml, options);
    const OccupancyGrid read = ReadMapServer(dir / yaml);
    EXPECT_EQ(back.width, read.width) << yaml;
    EXPECT_EQ(back.height, read.height) << yaml;
    EXPECT_EQ(back.cells, read.cells) << yaml;
    EXPECT_EQ(back.resolution_m, read.resolution_m) << yaml;
    EXPECT_EQ(back.origin.x_m, read.origin.x_m) << yaml;
    EXPECT_EQ(back.origin.y_m, read.origin.y_m) << yaml;
  }
}

TEST(MapServerFormatTest, TrinaryThresholdOptionsAreMapSaverOccAndFree) {
  testing::TempDir dir;
  OccupancyGrid grid(3, 1, 0.05, {}, 0.5f);
  grid.at(0, 0) = 0.1f;
  grid.at(0, 2) = 0.9f;
  MapWriteOptions options;
  options.occupied_threshold_percent = 50;
  options.free_threshold_percent = 10;
  WriteMapServer(grid, dir / "t.yaml", options);
  EXPECT_THAT(ReadMapServer(dir / "t.yaml").cells, ::testing::ElementsAre(0.0f, 1.0f, 1.0f));

  options.free_threshold_percent = 50;
  EXPECT_THAT(InputErrorOf([&] { WriteMapServer(grid, dir / "t.yaml", options); }),
              HasSubstr("option free_threshold_percent"));
  options = {};
  options.occupied_threshold_percent = 0;
  EXPECT_THAT(InputErrorOf([&] { WriteMapServer(grid, dir / "t.yaml", options); }),
              HasSubstr("option occupied_threshold_percent"));
}

TEST(MapServerFormatTest, ScaleWriteKeepsGreyLevelsAndMarksUnknownWithAlpha) {
  testing::TempDir dir;
  OccupancyGrid grid(7, 1, 0.05);
  const std::vector<float> values = {0.0f, 1.0f, 0.5f, 0.4f, 0.1f, 0.8f, OccupancyGrid::kUnknown};
  grid.cells = values;
  MapWriteOptions options;
  options.mode = MapWriteOptions::Mode::kScale;
  WriteMapServer(grid, dir / "s.yaml", options);

  const std::string yaml = map_test::ReadAll(dir / "s.yaml");
  EXPECT_THAT(yaml, StartsWith("image: s.png\n"));
  EXPECT_THAT(yaml, HasSubstr("\nmode: scale\n"));
  EXPECT_THAT(yaml, HasSubstr("# unknown cells: alpha 0"));
  EXPECT_FALSE(std::filesystem::exists(dir / "s.pgm"));

  const cv::Mat png = cv::imread((dir / "s.png").string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(png.type(), CV_8UC4);
  // grey = round(255 (1 - p)): 255, 0, 128 (127.5 rounds up), 153, 229.5 - float 0.1 is just above 0.1 - so 229, 51.
  const std::vector<int> greys = {255, 0, 128, 153, 229, 51};
  for (int col = 0; col < 6; ++col) {
    EXPECT_EQ(png.at<cv::Vec4b>(0, col), cv::Vec4b(greys[col], greys[col], greys[col], 255)) << col;
  }
  EXPECT_EQ(png.at<cv::Vec4b>(0, 6)[3], 0);

  // map_server's scale rules with 0.65 / 0.196: 128 -> occ 0.498, ratio 0.665 -> 65; 153 -> occ 0.4,
  // ratio 0.449 -> 44; 229 -> occ 0.102 < 0.196 -> free; 51 -> occ 0.8 -> occupied.
  EXPECT_THAT(ReadMapServer(dir / "s.yaml").cells,
              ::testing::ElementsAre(0.0f, 1.0f, 0.65f, 0.44f, 0.0f, 1.0f, OccupancyGrid::kUnknown));
}

TEST(MapServerFormatTest, WriteRejectsMalformedGridsAndUnwritablePaths) {
  testing::TempDir dir;
  OccupancyGrid grid(2, 2, 0.05, {}, 0.0f);
  grid.at(1, 1) = 2.0f;
  EXPECT_THAT(InputErrorOf([&] { WriteMapServer(grid, dir / "x.yaml"); }), HasSubstr("row 1, column 1"));
  grid.at(1, 1) = 0.0f;
  grid.resolution_m = 0.0;
  EXPECT_THAT(InputErrorOf([&] { WriteMapServer(grid, dir / "x.yaml"); }), HasSubstr("resolution"));
  grid.resolution_m = 0.05;
  EXPECT_THAT(InputErrorOf([&] { WriteMapServer(grid, "/nonexistent/slamsweep/x.yaml"); }),
              HasSubstr("/nonexistent/slamsweep/x.pgm"));
}

// ---- reference maps ----

/// The PGM header and pixel bytes, parsed here independently of the reader under test.
struct RawPgm {
  int width = 0;
  int height = 0;
  std::string pixels;
};

RawPgm ParseRawPgm(const std::filesystem::path& path) {
  const std::string bytes = map_test::ReadAll(path);
  std::istringstream header(bytes);
  std::string magic;
  int maxval = 0;
  RawPgm pgm;
  header >> magic;
  // Skip comment lines between the fields (map_saver writes one).
  const auto skip_comments = [&] {
    header >> std::ws;
    while (header.peek() == '#') {
      std::string ignored;
      std::getline(header, ignored);
      header >> std::ws;
    }
  };
  skip_comments();
  header >> pgm.width;
  skip_comments();
  header >> pgm.height;
  skip_comments();
  header >> maxval;
  EXPECT_EQ(magic, "P5");
  EXPECT_EQ(maxval, 255);
  const std::size_t data_start = static_cast<std::size_t>(header.tellg()) + 1;
  pgm.pixels = bytes.substr(data_start);
  return pgm;
}

struct TrinaryCounts {
  std::size_t occupied = 0;
  std::size_t free = 0;
  std::size_t unknown = 0;
};

void CheckReferenceMap(const std::filesystem::path& yaml, int width, int height, double resolution_m, double x_m,
                       double y_m) {
  const std::filesystem::path pgm_path = yaml.parent_path() / (yaml.stem().string() + ".pgm");
  const RawPgm raw = ParseRawPgm(pgm_path);
  ASSERT_EQ(raw.width, width);
  ASSERT_EQ(raw.height, height);
  ASSERT_EQ(raw.pixels.size(), static_cast<std::size_t>(width) * height);

  const OccupancyGrid grid = ReadMapServer(yaml);
  ASSERT_EQ(grid.width, width);
  ASSERT_EQ(grid.height, height);
  EXPECT_DOUBLE_EQ(grid.resolution_m, resolution_m);
  EXPECT_DOUBLE_EQ(grid.origin.x_m, x_m);
  EXPECT_DOUBLE_EQ(grid.origin.y_m, y_m);
  EXPECT_DOUBLE_EQ(grid.origin.yaw_rad, 0.0);

  // map_server trinary with the YAML's thresholds 0.65 / 0.196, byte by byte in file order.
  TrinaryCounts expected;
  TrinaryCounts read;
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < raw.pixels.size(); ++i) {
    const double occ = (255.0 - static_cast<unsigned char>(raw.pixels[i])) / 255.0;
    const float want = occ > 0.65 ? 1.0f : (occ < 0.196 ? 0.0f : OccupancyGrid::kUnknown);
    (want == 1.0f ? expected.occupied : want == 0.0f ? expected.free : expected.unknown)++;
    const float got = grid.cells[i];
    (got == 1.0f ? read.occupied : got == 0.0f ? read.free : read.unknown)++;
    if (got != want && ++mismatches <= 3) ADD_FAILURE() << "cell " << i << ": got " << got << ", want " << want;
  }
  EXPECT_EQ(read.occupied, expected.occupied);
  EXPECT_EQ(read.free, expected.free);
  EXPECT_EQ(read.unknown, expected.unknown);
  EXPECT_EQ(read.occupied + read.free + read.unknown, static_cast<std::size_t>(width) * height);
  EXPECT_GT(expected.occupied, 0u);
  EXPECT_GT(expected.free, 0u);
}

TEST(MapServerFormatTest, ReferenceTelecomIcpMap) {
  SLAMSWEEP_REQUIRE_SHARED(yaml, "reference/maps/telecom_icp.yaml");
  CheckReferenceMap(yaml, 1500, 1760, 0.05, -40.0, -52.0);
}

TEST(MapServerFormatTest, ReferenceTelecomRbpfMap) {
  SLAMSWEEP_REQUIRE_SHARED(yaml, "reference/maps/telecom_rbpf.yaml");
  CheckReferenceMap(yaml, 1272, 1357, 0.07, -48.02000045776367, -52.9900016784668);
}

}  // namespace
}  // namespace slamsweep::evaluator
