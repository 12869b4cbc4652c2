#include "evaluator/formats/map/map_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/evaluator/formats/map/map_test_helpers.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using map_test::InputErrorOf;
using ::testing::HasSubstr;

TEST(MapFileTest, DispatchesOnNameAndSiblingLimits) {
  testing::TempDir dir;
  map_test::WriteImage(dir / "bare.png", cv::Mat(1, 1, CV_8UC1, cv::Scalar(0)));
  map_test::WriteImage(dir / "mrpt.png", cv::Mat(1, 1, CV_8UC1, cv::Scalar(0)));
  testing::WriteFile(dir / "mrpt_limits.txt", "0 1 0 1\n");
  EXPECT_EQ(DetectMapFormat(dir / "m.yaml"), MapFormat::kRosMapServer);
  EXPECT_EQ(DetectMapFormat(dir / "m.YML"), MapFormat::kRosMapServer);
  EXPECT_EQ(DetectMapFormat(dir / "mrpt.png"), MapFormat::kMrptGridmap);
  EXPECT_EQ(DetectMapFormat(dir / "bare.png"), MapFormat::kBareImage);
  EXPECT_EQ(DetectMapFormat(dir / "map.pgm"), MapFormat::kBareImage);
  MapReadOptions explicit_format;
  explicit_format.format = MapFormat::kBareImage;
  EXPECT_EQ(DetectMapFormat(dir / "mrpt.png", explicit_format), MapFormat::kBareImage);
  EXPECT_THAT(InputErrorOf([&] { DetectMapFormat(dir / "map.txt"); }), HasSubstr("unknown map format"));
}

TEST(MapFileTest, ReadMapUsesTheDetectedReader) {
  testing::TempDir dir;
  map_test::WriteImage(dir / "mrpt.png", cv::Mat(2, 2, CV_8UC1, cv::Scalar(127)));
  testing::WriteFile(dir / "mrpt_limits.txt", "0 4 0 4\n");
  const OccupancyGrid mrpt = ReadMap(dir / "mrpt.png");
  EXPECT_DOUBLE_EQ(mrpt.resolution_m, 2.0);
  EXPECT_EQ(std::count(mrpt.cells.begin(), mrpt.cells.end(), OccupancyGrid::kUnknown), 4);

  MapReadOptions bare;
  bare.format = MapFormat::kBareImage;
  const OccupancyGrid as_bare = ReadMap(dir / "mrpt.png", bare);
  EXPECT_DOUBLE_EQ(as_bare.resolution_m, 0.05);
  EXPECT_FLOAT_EQ(as_bare.at(0, 0), 128.0f / 255.0f);

  testing::WriteFile(dir / "g.pgm", map_test::Pgm(1, 1, {0}));
  testing::WriteFile(dir / "m.yaml",
                     "image: g.pgm\nresolution: 0.2\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\n"
                     "free_thresh: 0.196\n");
  const OccupancyGrid ros = ReadMap(dir / "m.yaml");
  EXPECT_DOUBLE_EQ(ros.resolution_m, 0.2);
  EXPECT_EQ(ros.cells, std::vector<float>{1.0f});
}

TEST(MapFileTest, BareImageIsAllKnownUnlessAnUnknownValueIsGiven) {
  testing::TempDir dir;
  testing::WriteFile(dir / "b.pgm", map_test::Pgm(3, 1, {0, 205, 254}));
  const OccupancyGrid known = ReadMap(dir / "b.pgm");
  EXPECT_THAT(known.cells, ::testing::ElementsAre(1.0f, 50.0f / 255.0f, 1.0f / 255.0f));
  EXPECT_DOUBLE_EQ(known.resolution_m, 0.05);
  EXPECT_DOUBLE_EQ(known.origin.x_m, 0.0);
  EXPECT_DOUBLE_EQ(known.origin.y_m, 0.0);

  MapReadOptions options;
  options.unknown_value = 205;
  options.default_resolution_m = 0.1;
  const OccupancyGrid with_unknown = ReadMap(dir / "b.pgm", options);
  EXPECT_THAT(with_unknown.cells, ::testing::ElementsAre(1.0f, OccupancyGrid::kUnknown, 1.0f / 255.0f));
  EXPECT_DOUBLE_EQ(with_unknown.resolution_m, 0.1);
}

TEST(MapFileTest, MapWithoutKnownCellsIsReadable) {
  testing::TempDir dir;
  testing::WriteFile(dir / "u.pgm", map_test::Pgm(2, 2, std::vector<std::uint8_t>(4, 205)));
  MapReadOptions options;
  options.unknown_value = 205;
  const OccupancyGrid grid = ReadMap(dir / "u.pgm", options);
  EXPECT_EQ(std::count(grid.cells.begin(), grid.cells.end(), OccupancyGrid::kUnknown), 4);
}

TEST(MapFileTest, BadOptionsNameTheOption) {
  testing::TempDir dir;
  testing::WriteFile(dir / "b.pgm", map_test::Pgm(1, 1, {0}));
  MapReadOptions options;
  options.unknown_value = 300;
  EXPECT_THAT(InputErrorOf([&] { ReadMap(dir / "b.pgm", options); }), HasSubstr("option unknown_value"));
  options = {};
  options.default_resolution_m = -1.0;
  EXPECT_THAT(InputErrorOf([&] { ReadMap(dir / "b.pgm", options); }), HasSubstr("option default_resolution_m"));
}

TEST(MapFileTest, ColourBareImageIsRejected) {
  testing::TempDir dir;
  map_test::WriteImage(dir / "c.png", map_test::RgbRow({cv::Vec3b(0, 0, 255)}));
  EXPECT_THAT(InputErrorOf([&] { ReadMap(dir / "c.png"); }), HasSubstr("colour image"));
}

// ---- reference maps, against the values of an independent implementation ----

nlohmann::json ExpectedPaperMetrics(const std::filesystem::path& path, const std::string& map) {
  std::ifstream in(path);
  const nlohmann::json all = nlohmann::json::parse(in);
  for (const nlohmann::json& entry : all.at("maps")) {
    if (entry.at("map") == map) return entry;
  }
  ADD_FAILURE() << map << " not in " << path;
  return {};
}

/// Reads a reference PGM as a bare map (unknown = 205, p = (255 - v) / 255, as the reference
/// README says) and compares size, unknown share and mean p (the paper's threshold, unknown
/// counted as p = 0) with expected_paper_metrics.json.
void CheckBareReference(const std::filesystem::path& pgm, const std::filesystem::path& json) {
  const nlohmann::json expected = ExpectedPaperMetrics(json, pgm.filename().string());
  MapReadOptions options;
  options.unknown_value = expected.at("unknown_value").get<int>();
  const OccupancyGrid grid = ReadMap(pgm, options);
  ASSERT_EQ(grid.width, expected.at("width").get<int>());
  ASSERT_EQ(grid.height, expected.at("height").get<int>());
  const double cells = static_cast<double>(grid.CellCount());
  const auto unknown = std::count(grid.cells.begin(), grid.cells.end(), OccupancyGrid::kUnknown);
  EXPECT_EQ(unknown, std::llround(expected.at("unknown_to_all").get<double>() * cells));
  double sum = 0.0;
  for (const float p : grid.cells) sum += OccupancyGrid::IsUnknown(p) ? 0.0 : static_cast<double>(p);
  // Cells hold float: the mean agrees to float precision, not to the reference's 1e-9.
  EXPECT_NEAR(sum / cells, expected.at("threshold").get<double>(), 1e-7);
}

TEST(MapFileTest, ReferenceFastSlamMapAsBareImage) {
  SLAMSWEEP_REQUIRE_SHARED(pgm, "reference/maps/fastslam_thirdparty.pgm");
  SLAMSWEEP_REQUIRE_SHARED(json, "reference/maps/expected_paper_metrics.json");
  CheckBareReference(pgm, json);
}

TEST(MapFileTest, ReferenceTelecomMapsAsBareImages) {
  SLAMSWEEP_REQUIRE_SHARED(icp, "reference/maps/telecom_icp.pgm");
  SLAMSWEEP_REQUIRE_SHARED(rbpf, "reference/maps/telecom_rbpf.pgm");
  SLAMSWEEP_REQUIRE_SHARED(json, "reference/maps/expected_paper_metrics.json");
  CheckBareReference(icp, json);
  CheckBareReference(rbpf, json);
}

}  // namespace
}  // namespace slamsweep::evaluator
