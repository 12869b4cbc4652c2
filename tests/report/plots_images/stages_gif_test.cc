#include "report/images/stages_gif.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

#include "evaluator/core/input_error.h"
#include "report/images/grey_gif_writer.h"
#include "tests/report/plots_images/gif_reader.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

using evaluator::InputError;
using ::testing::HasSubstr;

/// A map that grows with `step`: unknown (205) everywhere, a free (254) square of side
/// 40 * (step + 1) cells in the top-left corner with an occupied (0) wall on its right edge.
/// Every feature is a multiple of 2 cells, so a 2:1 area reduction reproduces it exactly.
cv::Mat GrowingMap(int side, int step) {
  cv::Mat map(side, side, CV_8UC1, cv::Scalar(205));
  const int extent = std::min(side, 40 * (step + 1));
  map(cv::Rect(0, 0, extent, extent)).setTo(254);
  map(cv::Rect(extent - 2, 0, 2, extent)).setTo(0);
  return map;
}

/// `known_corner`: one free cell in the bottom-right corner of every stage, so that the known part of
/// the stages spans the whole image and the canvas rule crops nothing.
std::vector<std::filesystem::path> WriteStages(const std::filesystem::path& dir, int count, int side,
                                               bool known_corner = false) {
  std::vector<std::filesystem::path> paths;
  for (int i = 0; i < count; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "stage_%04d.png", i);
    paths.push_back(dir / name);
    cv::Mat map = GrowingMap(side, i);
    if (known_corner) map.at<uchar>(side - 1, side - 1) = 254;
    EXPECT_TRUE(cv::imwrite(paths.back().string(), map));
  }
  return paths;
}

TEST(WriteStagesGifTest, OneFramePerStageWithDelaysAndLoop) {
  testing::TempDir dir;
  const auto stages = WriteStages(dir.path(), 6, 400, /*known_corner=*/true);
  const GifOptions options{.max_side_px = 480, .frame_delay_cs = 15, .last_frame_delay_cs = 150};
  WriteStagesGif(stages, dir / "map.gif", options);
  const gif_check::DecodedGif gif = gif_check::DecodeGif(dir / "map.gif");
  EXPECT_EQ(gif.width, 400);  // never enlarged
  EXPECT_EQ(gif.height, 400);
  EXPECT_TRUE(gif.loops_forever);
  EXPECT_EQ(gif.delays_cs, (std::vector<int>{15, 15, 15, 15, 15, 150}));
  ASSERT_EQ(gif.canvases.size(), 6u);
  for (int i = 0; i < 6; ++i) {
    cv::Mat expected = GrowingMap(400, i);
    expected.at<uchar>(399, 399) = 254;
    EXPECT_EQ(cv::norm(gif.canvases[i], expected, cv::NORM_INF), 0.0) << "frame " << i;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "map.gif.tmp"));
}

TEST(WriteStagesGifTest, UnchangedCellsAreTransparentAndATrinaryMapIsCodedOnTwoBits) {
  // 24 stages of a 400 x 400 map with scattered walls that grows by a band each stage: every frame's
  // rectangle holds the whole known part, of which only the new band changed.
  testing::TempDir dir;
  std::vector<GreyFrame> frames;
  cv::Mat map(400, 400, CV_8UC1, cv::Scalar(205));
  for (int stage = 0; stage < 24; ++stage) {
    for (int row = 0; row < 400; ++row) {
      for (int col = 16 * stage; col < 16 * stage + 16; ++col) {
        map.at<uchar>(row, col) = (row * 7919 + col * 104729) % 13 == 0 ? 0 : 254;
      }
    }
    map.at<uchar>(399, 0) = stage % 2 == 0 ? 0 : 254;  // a cell that flips: the rectangle spans the map
    frames.push_back({map.clone(), 15});
  }
  const GifWriteOutcome written = WriteGreyGif(frames, dir / "map.gif");
  const gif_check::DecodedGif gif = gif_check::DecodeGif(dir / "map.gif");
  ASSERT_EQ(gif.canvases.size(), frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(cv::norm(gif.canvases[i], frames[i].image, cv::NORM_INF), 0.0) << "frame " << i;
  }
  // Coded as the new bands alone at 2 bits a pixel would take 24 x 16 x 400 / 4 bytes before LZW;
  // 8-bit codes over every frame's whole rectangle took several times that.
  EXPECT_LT(written.bytes, 24u * 16u * 400u / 4u);
}

TEST(WriteStagesGifTest, ShrinksToMaxSideWithAreaInterpolation) {
  testing::TempDir dir;
  const auto stages = WriteStages(dir.path(), 3, 960, /*known_corner=*/true);
  WriteStagesGif(stages, dir / "map.gif", {.max_side_px = 480});
  const gif_check::DecodedGif gif = gif_check::DecodeGif(dir / "map.gif");
  EXPECT_EQ(gif.width, 480);
  EXPECT_EQ(gif.height, 480);
  ASSERT_EQ(gif.canvases.size(), 3u);
  // A 2:1 area reduction of a map made of 2x2 blocks is the map at half scale: a free square of
  // 20 * (step + 1) pixels with a one-pixel wall on its right edge.
  const cv::Mat& last = gif.canvases.back();
  EXPECT_EQ(last.at<uchar>(0, 0), 254);
  EXPECT_EQ(last.at<uchar>(10, 59), 0);
  EXPECT_EQ(last.at<uchar>(10, 58), 254);
  EXPECT_EQ(last.at<uchar>(10, 60), 205);
  EXPECT_EQ(last.at<uchar>(60, 10), 205);
}

TEST(WriteStagesGifTest, UnknownPaddingAroundStagesOfOneSizeIsCropped) {
  // The canvas rule of the map metrics, for the animation: the union of the known cells of all
  // stages plus 2, so a program that draws on a huge canvas shows its map as large as the others.
  testing::TempDir dir;
  const auto stages = WriteStages(dir.path(), 6, 400);
  WriteStagesGif(stages, dir / "map.gif", {});
  const gif_check::DecodedGif gif = gif_check::DecodeGif(dir / "map.gif");
  // The last stage's free square is 240 x 240 at the top-left: 242 x 242 with the margin.
  EXPECT_EQ(gif.width, 242);
  EXPECT_EQ(gif.height, 242);
  ASSERT_EQ(gif.canvases.size(), 6u);
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(cv::norm(gif.canvases[i], GrowingMap(400, i)(cv::Rect(0, 0, 242, 242)), cv::NORM_INF), 0.0)
        << "frame " << i;
  }
}

TEST(WriteStagesGifTest, StagesOfDifferentSizesAreCentredOnUnknown) {
  testing::TempDir dir;
  ASSERT_TRUE(cv::imwrite((dir / "s0.png").string(), cv::Mat(20, 40, CV_8UC1, cv::Scalar(254))));
  ASSERT_TRUE(cv::imwrite((dir / "s1.png").string(), cv::Mat(60, 80, CV_8UC1, cv::Scalar(0))));
  WriteStagesGif({dir / "s0.png", dir / "s1.png"}, dir / "map.gif", {});
  const gif_check::DecodedGif gif = gif_check::DecodeGif(dir / "map.gif");
  EXPECT_EQ(gif.width, 80);
  EXPECT_EQ(gif.height, 60);
  ASSERT_EQ(gif.canvases.size(), 2u);
  // The 40 x 20 stage sits at (20, 20) on the 80 x 60 canvas.
  EXPECT_EQ(gif.canvases[0].at<uchar>(19, 19), 205);
  EXPECT_EQ(gif.canvases[0].at<uchar>(20, 20), 254);
  EXPECT_EQ(gif.canvases[0].at<uchar>(39, 59), 254);
  EXPECT_EQ(gif.canvases[0].at<uchar>(40, 60), 205);
  EXPECT_EQ(cv::countNonZero(gif.canvases[1]), 0);
}

TEST(WriteStagesGifTest, SizeCapHoldsForTwoHundredLargeNoisyStages) {
  testing::TempDir dir;
  // Ten distinct 2000 x 2000 maps of random 8 x 8 blocks (noise compresses badly, so the cap bites),
  // used twenty times each: 200 stages.
  std::mt19937 random(7);
  std::vector<std::filesystem::path> distinct;
  for (int k = 0; k < 10; ++k) {
    cv::Mat blocks(250, 250, CV_8UC1);
    for (int r = 0; r < blocks.rows; ++r) {
      for (int c = 0; c < blocks.cols; ++c) blocks.at<uchar>(r, c) = static_cast<uchar>(random() % 3 == 0 ? 0 : 254);
    }
    cv::Mat map;
    cv::resize(blocks, map, {2000, 2000}, 0, 0, cv::INTER_NEAREST);
    distinct.push_back(dir / ("noise" + std::to_string(k) + ".png"));
    ASSERT_TRUE(cv::imwrite(distinct.back().string(), map));
  }
  std::vector<std::filesystem::path> stages;
  for (int i = 0; i < 200; ++i) stages.push_back(distinct[i % 10]);

  const GifOptions options;  // 480 px, 2 MiB
  WriteStagesGif(stages, dir / "big.gif", options);
  EXPECT_LE(std::filesystem::file_size(dir / "big.gif"), options.max_bytes);
  const gif_check::DecodedGif gif = gif_check::DecodeGif(dir / "big.gif");
  EXPECT_LE(std::max(gif.width, gif.height), 480);
  EXPECT_GE(gif.canvases.size(), 2u);
  EXPECT_LT(gif.canvases.size(), 200u);
  EXPECT_TRUE(gif.loops_forever);
  EXPECT_EQ(gif.delays_cs.back(), options.last_frame_delay_cs);
}

TEST(WriteStagesGifTest, TinyCapShrinksTheAnimation) {
  testing::TempDir dir;
  const auto stages = WriteStages(dir.path(), 12, 400);
  // Also noisy content: a cap of 4 KiB cannot hold 12 full frames of 400 px.
  std::mt19937 random(3);
  for (const auto& path : stages) {
    cv::Mat map(400, 400, CV_8UC1);
    for (int r = 0; r < map.rows; ++r) {
      for (int c = 0; c < map.cols; ++c) map.at<uchar>(r, c) = static_cast<uchar>(random() % 256);
    }
    ASSERT_TRUE(cv::imwrite(path.string(), map));
  }
  WriteStagesGif(stages, dir / "tiny.gif", {.max_bytes = 4096});
  EXPECT_LE(std::filesystem::file_size(dir / "tiny.gif"), 4096u);
  const gif_check::DecodedGif gif = gif_check::DecodeGif(dir / "tiny.gif");
  EXPECT_LT(gif.width, 400);
  EXPECT_GE(gif.canvases.size(), 2u);
}

TEST(WriteStagesGifTest, BadInputIsAnInputErrorNamingIt) {
  testing::TempDir dir;
  EXPECT_THROW(WriteStagesGif({}, dir / "x.gif", {}), InputError);
  testing::WriteFile(dir / "text.png", "this is not a PNG");
  try {
    WriteStagesGif({dir / "text.png"}, dir / "x.gif", {});
    FAIL() << "expected an error";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("text.png"));
  }
  try {
    WriteStagesGif({dir / "missing.png"}, dir / "x.gif", {});
    FAIL() << "expected an error";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("missing.png"));
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "x.gif"));
}

TEST(WriteStagesGifTest, BadOptionsAreNamed) {
  const auto message = [](const GifOptions& options) {
    try {
      ValidateGifOptions(options);
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(message({.max_side_px = 2}), HasSubstr("max_side_px"));
  EXPECT_THAT(message({.max_bytes = 100}), HasSubstr("max_bytes"));
  EXPECT_THAT(message({.frame_delay_cs = -1}), HasSubstr("frame_delay_cs"));
  EXPECT_THAT(message({.last_frame_delay_cs = 70000}), HasSubstr("last_frame_delay_cs"));
  EXPECT_EQ(message({}), "no error");
}

}  // namespace
}  // namespace slamsweep::report

namespace slamsweep::report {
namespace {

TEST(WriteGreyGifTest, RejectsFramesOfAnotherSizeOrType) {
  testing::TempDir dir;
  const std::vector<GreyFrame> sizes = {{cv::Mat(10, 10, CV_8UC1, cv::Scalar(1)), 5},
                                        {cv::Mat(10, 11, CV_8UC1, cv::Scalar(1)), 5}};
  EXPECT_THROW(WriteGreyGif(sizes, dir / "a.gif"), std::invalid_argument);
  const std::vector<GreyFrame> colour = {{cv::Mat(10, 10, CV_8UC3), 5}};
  EXPECT_THROW(WriteGreyGif(colour, dir / "b.gif"), std::invalid_argument);
  EXPECT_THROW(WriteGreyGif(std::vector<GreyFrame>{}, dir / "c.gif"), std::invalid_argument);
}

TEST(WriteGreyGifTest, GivesUpEarlyPastTheByteLimit) {
  testing::TempDir dir;
  std::mt19937 random(5);
  int made = 0;
  const auto noise = [&](std::size_t) {
    ++made;
    cv::Mat image(200, 200, CV_8UC1);
    for (int r = 0; r < 200; ++r) {
      for (int c = 0; c < 200; ++c) image.at<uchar>(r, c) = static_cast<uchar>(random());
    }
    return GreyFrame{image, 10};
  };
  // A noise frame of 200 x 200 takes over 40 kB; a 50 kB limit is passed after a frame or two.
  const GifWriteOutcome outcome = WriteGreyGif(50, noise, dir / "n.gif", 50000);
  EXPECT_FALSE(outcome.complete);
  EXPECT_LE(outcome.frames_written, 3u);
  EXPECT_EQ(made, static_cast<int>(outcome.frames_written));
  EXPECT_GT(outcome.bytes, 50000u);
}

}  // namespace
}  // namespace slamsweep::report

namespace slamsweep::report {
namespace {

TEST(WriteStagesGifTest, HeaderClaimingAHugeImageIsAnInputError) {
  testing::TempDir dir;
  // A PGM header claiming 1,000,000 x 1,000,000 pixels, with no pixels behind it.
  testing::WriteFile(dir / "huge.pgm", "P5\n1000000 1000000\n255\n");
  try {
    WriteStagesGif({dir / "huge.pgm"}, dir / "x.gif", {});
    FAIL() << "expected an error";
  } catch (const evaluator::InputError& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("huge.pgm"));
  }
}

}  // namespace
}  // namespace slamsweep::report
