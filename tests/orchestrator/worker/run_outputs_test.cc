// The run folder's converted outputs (run_outputs.h): the stage animation's size cap.
#include "orchestrator/worker/run_outputs.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>

#include <opencv2/core.hpp>

#include "evaluator/formats/map/animated_png_reader.h"
#include "evaluator/core/text_file.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

namespace ev = slamsweep::evaluator;

/// A trinary stage of `rows` x `cols`: unknown, a free band and a wall one cell thick at column `wall`.
cv::Mat Stage(int rows, int cols, int wall) {
  cv::Mat stage(rows, cols, CV_8UC1, cv::Scalar(205));
  stage(cv::Rect(0, rows / 4, cols, rows / 2)).setTo(254);
  stage.col(wall).setTo(0);
  return stage;
}

CollectedOutputs Collected(const std::vector<cv::Mat>& stages) {
  CollectedOutputs collected;
  collected.map = ev::OccupancyGrid(8, 8, 0.05, {}, 0.0f);
  collected.stages = stages;
  return collected;
}

TEST(RunOutputsTest, AStageAnimationOverTheSideCapIsReducedByAWholeFactorKeepingWallsAndFreeSpace) {
  slamsweep::testing::TempDir dir;
  const RunPaths paths{dir.path()};
  // 1,000 x 700 cells: a factor of 4 brings the longer side to 250 (at most 256).
  const nlohmann::json outputs =
      WriteRunOutputs(paths, Collected({Stage(700, 1000, 500), Stage(700, 1000, 601)}), nullptr);
  EXPECT_EQ(outputs["stage_count"], 2u);
  const std::vector<cv::Mat> frames = ev::DecodeAnimatedGreyPng(ev::ReadTextFile(paths.StageAnimation()), "stages.png");
  ASSERT_EQ(frames.size(), 2u);
  for (const cv::Mat& frame : frames) {
    EXPECT_EQ(frame.cols, 250);
    EXPECT_EQ(frame.rows, 175);
  }
  // The one-cell walls survive the reduction (occupied wins in its block), as do free and unknown.
  EXPECT_EQ(frames[0].at<std::uint8_t>(87, 500 / 4), 0);
  EXPECT_EQ(frames[1].at<std::uint8_t>(87, 601 / 4), 0);
  EXPECT_EQ(frames[1].at<std::uint8_t>(87, 500 / 4), 254);
  EXPECT_EQ(frames[0].at<std::uint8_t>(0, 0), 205);
}

TEST(RunOutputsTest, AStageAnimationOverTheByteCapIsReducedUntilItFits) {
  slamsweep::testing::TempDir dir;
  const RunPaths paths{dir.path()};
  // Cells drawn at random from the three greys: nothing for deflate to find, over 14 KB even at half the side.
  cv::RNG draw(7);
  std::vector<cv::Mat> stages;
  for (int i = 0; i < 3; ++i) {
    cv::Mat stage(390, 390, CV_8UC1);
    for (int row = 0; row < stage.rows; ++row) {
      for (int col = 0; col < stage.cols; ++col) {
        stage.at<std::uint8_t>(row, col) = std::array<std::uint8_t, 3>{0, 205, 254}[draw.uniform(0, 3)];
      }
    }
    stages.push_back(stage);
  }
  WriteRunOutputs(paths, Collected(stages), nullptr);
  EXPECT_LE(std::filesystem::file_size(paths.StageAnimation()), 14u << 10);
  const std::vector<cv::Mat> frames = ev::DecodeAnimatedGreyPng(ev::ReadTextFile(paths.StageAnimation()), "stages.png");
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_LT(frames[0].cols, 390 / 2);
}

TEST(RunOutputsTest, AStageAnimationWithinTheSideCapKeepsEveryCell) {
  slamsweep::testing::TempDir dir;
  const RunPaths paths{dir.path()};
  const cv::Mat stage = Stage(200, 250, 7);
  WriteRunOutputs(paths, Collected({stage}), nullptr);
  const std::vector<cv::Mat> frames = ev::DecodeAnimatedGreyPng(ev::ReadTextFile(paths.StageAnimation()), "stages.png");
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(cv::countNonZero(frames[0] != stage), 0);
}

}  // namespace
}  // namespace slamsweep::orchestrator
