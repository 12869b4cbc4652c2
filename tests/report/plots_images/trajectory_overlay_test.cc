#include "report/images/trajectory_overlay.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgcodecs.hpp>

#include "evaluator/core/input_error.h"
#include "evaluator/core/occupancy_grid.h"
#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

using evaluator::Pose;
using evaluator::Trajectory;

/// A 200 x 100 cell free map at 0.05 m, origin (-1, -2): world x in [-1, 9], y in [-2, 3].
/// Every cell is known, so the view is the whole map and a 800 px picture is 4 px per cell:
/// world (x, y) is pixel column 80 (x + 1), row 4 (100 - 20 (y + 2)).
class TrajectoryOverlayTest : public ::testing::Test {
 protected:
  void SetUp() override {
    evaluator::WriteMapServer(evaluator::OccupancyGrid(200, 100, 0.05, {-1.0, -2.0, 0.0}, 0.0f), dir_ / "map.yaml");
  }

  /// The line y = y_m from x = 0 to x = 6 m, 61 poses 0.1 s apart, seen from `frame`.
  std::filesystem::path WriteLine(const std::string& name, double y_m, const Pose& frame = Pose()) {
    Trajectory line;
    for (int i = 0; i <= 60; ++i) line.Add(i * 0.1, frame * Pose::Planar(i * 0.1, y_m, 0.0));
    evaluator::WriteTum(line, dir_ / name);
    return dir_ / name;
  }

  static bool Near(const cv::Vec3b& pixel, const unsigned char (&bgr)[3], int tolerance = 40) {
    for (int k = 0; k < 3; ++k) {
      if (std::abs(pixel[k] - bgr[k]) > tolerance) return false;
    }
    return true;
  }

  /// Whether a pixel of colour `bgr` lies in rows row0..row1 of column `col`.
  static bool ColourInColumn(const cv::Mat& image, int col, int row0, int row1, const unsigned char (&bgr)[3]) {
    for (int r = row0; r <= row1; ++r) {
      if (Near(image.at<cv::Vec3b>(r, col), bgr)) return true;
    }
    return false;
  }

  static int CountNear(const cv::Mat& image, const unsigned char (&bgr)[3]) {
    int count = 0;
    for (int r = 0; r < image.rows; ++r) {
      for (int c = 0; c < image.cols; ++c) count += Near(image.at<cv::Vec3b>(r, c), bgr, 10) ? 1 : 0;
    }
    return count;
  }

  testing::TempDir dir_;
};

TEST_F(TrajectoryOverlayTest, DrawsEstimateAndUnalignedReferenceWhereTheyAre) {
  const auto estimate = WriteLine("estimate.tum", 0.0);
  const auto reference = WriteLine("reference.tum", 1.0);
  WriteTrajectoryOverlay(dir_ / "map.yaml", estimate, reference, dir_ / "overlay.png", {.align = "none"});
  const cv::Mat image = cv::imread((dir_ / "overlay.png").string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, 800);
  EXPECT_GT(image.rows, 400);  // the map plus the legend strip
  // Estimate y = 0 -> row 240; reference y = 1 -> row 160; both along columns 80 (x = 0) .. 560 (x = 6).
  for (const int col : {160, 320, 480}) {
    EXPECT_TRUE(ColourInColumn(image, col, 239, 241, kEstimateBgr)) << "column " << col;
    EXPECT_TRUE(ColourInColumn(image, col, 159, 161, kReferenceBgr)) << "column " << col;
    EXPECT_FALSE(ColourInColumn(image, col, 150, 170, kEstimateBgr)) << "column " << col;
    EXPECT_FALSE(ColourInColumn(image, col, 230, 250, kReferenceBgr)) << "column " << col;
    // Between the paths the map is free: white.
    EXPECT_EQ(image.at<cv::Vec3b>(200, col), cv::Vec3b(255, 255, 255));
  }
}

TEST_F(TrajectoryOverlayTest, ReferenceIsAlignedOntoTheEstimate) {
  const auto estimate = WriteLine("estimate.tum", 0.0);
  // The same line in another frame: se2 alignment brings it back under the estimate.
  const auto reference = WriteLine("reference.tum", 0.0, Pose::Planar(3.0, 2.0, 0.8));
  WriteTrajectoryOverlay(dir_ / "map.yaml", estimate, reference, dir_ / "overlay.png", {.align = "se2"});
  const cv::Mat image = cv::imread((dir_ / "overlay.png").string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  for (const int col : {160, 320, 480}) {
    EXPECT_TRUE(ColourInColumn(image, col, 239, 241, kEstimateBgr)) << "column " << col;
    // The wider reference shows on both sides of the estimate.
    EXPECT_TRUE(ColourInColumn(image, col, 236, 238, kReferenceBgr)) << "column " << col;
    EXPECT_TRUE(ColourInColumn(image, col, 242, 244, kReferenceBgr)) << "column " << col;
  }
}

TEST_F(TrajectoryOverlayTest, WithoutReferenceOnlyTheEstimateIsDrawn) {
  const auto estimate = WriteLine("estimate.tum", 0.0);
  WriteTrajectoryOverlay(dir_ / "map.yaml", estimate, {}, dir_ / "overlay.png", {});
  const cv::Mat image = cv::imread((dir_ / "overlay.png").string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  EXPECT_GT(CountNear(image, kEstimateBgr), 500);
  EXPECT_EQ(CountNear(image, kReferenceBgr), 0);
}

TEST_F(TrajectoryOverlayTest, ReferenceThatCannotBeAlignedIsLeftOut) {
  const auto estimate = WriteLine("estimate.tum", 0.0);
  Trajectory late;
  for (int i = 0; i < 10; ++i) late.Add(1000.0 + i, Pose::Planar(i, 0.0, 0.0));
  evaluator::WriteTum(late, dir_ / "late.tum");
  WriteTrajectoryOverlay(dir_ / "map.yaml", estimate, dir_ / "late.tum", dir_ / "overlay.png", {});
  const cv::Mat image = cv::imread((dir_ / "overlay.png").string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(CountNear(image, kReferenceBgr), 0);
}

TEST_F(TrajectoryOverlayTest, BadInputIsAnInputErrorNamingIt) {
  const auto estimate = WriteLine("estimate.tum", 0.0);
  const auto png = dir_ / "overlay.png";
  const auto message = [&](const std::filesystem::path& map, const std::filesystem::path& est,
                           const std::filesystem::path& ref, const OverlayOptions& options) {
    try {
      WriteTrajectoryOverlay(map, est, ref, png, options);
    } catch (const evaluator::InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(message(dir_ / "nomap.yaml", estimate, {}, {}), ::testing::HasSubstr("nomap.yaml"));
  EXPECT_THAT(message(dir_ / "map.yaml", dir_ / "none.tum", {}, {}), ::testing::HasSubstr("none.tum"));
  EXPECT_THAT(message(dir_ / "map.yaml", estimate, dir_ / "noref.tum", {}), ::testing::HasSubstr("noref.tum"));
  testing::WriteFile(dir_ / "bad.tum", "0 1 2 3 0 0 0 1\n1 x 2 3 0 0 0 1\n");
  EXPECT_THAT(message(dir_ / "map.yaml", dir_ / "bad.tum", {}, {}), ::testing::HasSubstr("bad.tum:2"));
  testing::WriteFile(dir_ / "empty.tum", "# nothing\n");
  EXPECT_THAT(message(dir_ / "map.yaml", dir_ / "empty.tum", {}, {}), ::testing::HasSubstr("empty.tum"));
  EXPECT_THAT(message(dir_ / "map.yaml", estimate, {}, {.align = "umeyama"}), ::testing::HasSubstr("umeyama"));
  EXPECT_THAT(message(dir_ / "map.yaml", estimate, {}, {.max_side_px = 10}), ::testing::HasSubstr("max_side_px"));
}

}  // namespace
}  // namespace slamsweep::report

namespace slamsweep::report {
namespace {

TEST(TrajectoryOverlayDivergedTest, FarAwayPosesKeepThePictureSmall) {
  testing::TempDir dir;
  evaluator::WriteMapServer(evaluator::OccupancyGrid(200, 100, 0.05, {-1.0, -2.0, 0.0}, 0.0f), dir / "map.yaml");
  Trajectory diverged;
  diverged.Add(0.0, Pose::Planar(0.0, 0.0, 0.0));
  diverged.Add(1.0, Pose::Planar(1e9, -1e12, 0.0));
  evaluator::WriteTum(diverged, dir / "diverged.tum");
  WriteTrajectoryOverlay(dir / "map.yaml", dir / "diverged.tum", {}, dir / "overlay.png", {});
  const cv::Mat image = cv::imread((dir / "overlay.png").string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  EXPECT_LE(image.cols, 800);
  EXPECT_LE(image.rows, 800 + 100);  // the map part plus the legend strip
}

}  // namespace
}  // namespace slamsweep::report
