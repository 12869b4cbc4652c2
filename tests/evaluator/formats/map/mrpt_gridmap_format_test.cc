#include "evaluator/formats/map/mrpt_gridmap_format.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/evaluator/formats/map/map_test_helpers.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using map_test::InputErrorOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;

/// The limits file as MRPT's CMatrixF::saveToTextFile(MATRIX_FORMAT_FIXED) writes it.
constexpr const char* kLimits =
    "% Grid limits: [x_min x_max y_min y_max]\n"
    "-1.0000000000000000 0.5000000000000000 2.0000000000000000 3.0000000000000000\n";

/// A 3 x 2 bitmap: row 0 (the top, largest y) = 0, 127, 255; row 1 = 51, 204, 127.
void WriteSample(const testing::TempDir& dir, const std::string& limits = kLimits) {
  cv::Mat image(2, 3, CV_8UC1);
  const uchar values[] = {0, 127, 255, 51, 204, 127};
  for (int i = 0; i < 6; ++i) image.at<uchar>(i / 3, i % 3) = values[i];
  map_test::WriteImage(dir / "run_COccupancyGridMap2D_00.png", image);
  testing::WriteFile(dir / "run_COccupancyGridMap2D_00_limits.txt", limits);
}

TEST(MrptGridmapFormatTest, LimitsFileSitsBesideTheBitmap) {
  EXPECT_EQ(MrptLimitsPath("/out/map_gridmap_no00.png"), std::filesystem::path("/out/map_gridmap_no00_limits.txt"));
}

TEST(MrptGridmapFormatTest, ReadsCellsExtentAndOrientation) {
  testing::TempDir dir;
  WriteSample(dir);
  const OccupancyGrid grid = ReadMrptGridmap(dir / "run_COccupancyGridMap2D_00.png");
  ASSERT_EQ(grid.width, 3);
  ASSERT_EQ(grid.height, 2);
  EXPECT_DOUBLE_EQ(grid.resolution_m, 0.5);  // (0.5 - -1.0) / 3 = (3 - 2) / 2
  EXPECT_DOUBLE_EQ(grid.origin.x_m, -1.0);
  EXPECT_DOUBLE_EQ(grid.origin.y_m, 2.0);
  // MRPT draws grid row y into image row height - 1 - y: the image's top row is the cells at
  // the largest y, centre y_min + (height - 0.5) * resolution = 2.75.
  EXPECT_DOUBLE_EQ(grid.CellCenterYM(0), 2.75);
  EXPECT_DOUBLE_EQ(grid.CellCenterXM(0), -0.75);
  EXPECT_THAT(grid.cells, ::testing::ElementsAre(1.0f, OccupancyGrid::kUnknown, 0.0f, 204.0f / 255.0f, 51.0f / 255.0f,
                                                 OccupancyGrid::kUnknown));
}

TEST(MrptGridmapFormatTest, UnknownValueCanBeOverridden) {
  testing::TempDir dir;
  WriteSample(dir);
  const OccupancyGrid grid = ReadMrptGridmap(dir / "run_COccupancyGridMap2D_00.png", 255);
  EXPECT_FLOAT_EQ(grid.at(0, 1), 128.0f / 255.0f);
  EXPECT_EQ(grid.at(0, 2), OccupancyGrid::kUnknown);
}

TEST(MrptGridmapFormatTest, RoundTripKeepsCellsAndExtent) {
  testing::TempDir dir;
  OccupancyGrid grid(4, 3, 0.07, GridOrigin{-48.02000045776367, -52.9900016784668, 0.0});
  for (std::size_t i = 0; i < grid.cells.size(); ++i) {
    const int grey = static_cast<int>(i * 23 % 256);
    grid.cells[i] = grey == 127 ? OccupancyGrid::kUnknown : static_cast<float>((255 - grey) / 255.0);
  }
  grid.cells[5] = OccupancyGrid::kUnknown;
  WriteMrptGridmap(grid, dir / "map.png");

  const std::string limits = map_test::ReadAll(dir / "map_limits.txt");
  EXPECT_THAT(limits, StartsWith("% Grid limits: [x_min x_max y_min y_max]\n-48.0200004577636"));

  const cv::Mat png = cv::imread((dir / "map.png").string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(png.type(), CV_8UC1);
  EXPECT_EQ(png.at<uchar>(1, 1), 127);  // cell 5 is unknown

  const OccupancyGrid back = ReadMrptGridmap(dir / "map.png");
  EXPECT_EQ(back.width, 4);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.cells, grid.cells);
  EXPECT_NEAR(back.resolution_m, 0.07, 1e-12);
  EXPECT_EQ(back.origin.x_m, grid.origin.x_m);
  EXPECT_EQ(back.origin.y_m, grid.origin.y_m);
}

TEST(MrptGridmapFormatTest, KnownCellAtMrptsUnknownGreyBecomesUnknown) {
  testing::TempDir dir;
  OccupancyGrid grid(2, 1, 0.1, {}, 0.502f);  // round(255 * 0.498) = 127
  grid.at(0, 1) = 0.5f;                       // 127.5 rounds to 128: stays known
  WriteMrptGridmap(grid, dir / "m.png");
  const OccupancyGrid back = ReadMrptGridmap(dir / "m.png");
  EXPECT_EQ(back.at(0, 0), OccupancyGrid::kUnknown);
  EXPECT_FLOAT_EQ(back.at(0, 1), 127.0f / 255.0f);
}

TEST(MrptGridmapFormatTest, MissingOrBadLimitsAreInputErrors) {
  testing::TempDir dir;
  map_test::WriteImage(dir / "alone.png", cv::Mat(2, 2, CV_8UC1, cv::Scalar(127)));
  const std::string missing = InputErrorOf([&] { ReadMrptGridmap(dir / "alone.png"); });
  EXPECT_THAT(missing, HasSubstr("alone.png"));
  EXPECT_THAT(missing, HasSubstr("alone_limits.txt"));

  const std::string path = (dir / "run_COccupancyGridMap2D_00_limits.txt").string();
  const auto error_with = [&](const std::string& limits) {
    WriteSample(dir, limits);
    return InputErrorOf([&] { ReadMrptGridmap(dir / "run_COccupancyGridMap2D_00.png"); });
  };
  EXPECT_THAT(error_with("% header\n-1 0.5 2\n"), StartsWith(path + ":2:"));
  EXPECT_THAT(error_with("-1 0.5 2 abc\n"), StartsWith(path + ":1: field 4 (y_max)"));
  EXPECT_THAT(error_with("-1 0.5 2 3 4\n"), HasSubstr("expected 4 numbers"));
  EXPECT_THAT(error_with("-1 0.5 2 3\n-1 0.5 2 3\n"), HasSubstr("second"));
  EXPECT_THAT(error_with("% nothing\n"), HasSubstr("no limits line"));
  EXPECT_THAT(error_with("1 -0.5 2 3\n"), HasSubstr("x_min < x_max"));
  // 0.5 m/cell along x, 1 m/cell along y.
  EXPECT_THAT(error_with("-1 0.5 2 4\n"), HasSubstr("square cells"));
}

TEST(MrptGridmapFormatTest, WriterRejectsRotatedOriginsAndOtherExtensions) {
  testing::TempDir dir;
  OccupancyGrid grid(2, 2, 0.1, GridOrigin{0.0, 0.0, 0.5}, 0.0f);
  EXPECT_THAT(InputErrorOf([&] { WriteMrptGridmap(grid, dir / "m.png"); }), HasSubstr("yaw"));
  grid.origin.yaw_rad = 0.0;
  EXPECT_THAT(InputErrorOf([&] { WriteMrptGridmap(grid, dir / "m.pgm"); }), HasSubstr(".png"));
}

}  // namespace
}  // namespace slamsweep::evaluator
