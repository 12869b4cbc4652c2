#include "evaluator/formats/map/compact_png.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "evaluator/core/input_error.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

/// A trinary stage map that grows: column block `step` and the ones before it become known.
cv::Mat Stage(int step) {
  cv::Mat stage(40, 70, CV_8UC1, cv::Scalar(205));
  for (int i = 0; i <= step; ++i) {
    stage(cv::Rect(5 + 10 * i, 5, 8, 30)).setTo(254);
    stage(cv::Rect(5 + 10 * i, 5, 8, 2)).setTo(0);
  }
  return stage;
}

/// The frames of `png` as Pillow composes them (tests/.../apng_frames.py); null with `why` when Pillow is missing.
nlohmann::json DecodeWithPillow(const std::string& png, std::string& why) {
  slamsweep::testing::TempDir dir;
  slamsweep::testing::WriteFile(dir / "in.png", png);
  const std::string command = std::string("/usr/bin/python3 '") + SLAMSWEEP_APNG_READER + "' '" +
                              (dir / "in.png").string() + "' > '" + (dir / "out.json").string() + "' 2> '" +
                              (dir / "err.txt").string() + "'";
  if (std::system(command.c_str()) != 0) {
    std::ifstream err(dir / "err.txt");
    why = "python3 with Pillow (apt-get install python3-pil) could not read the PNG: " +
          std::string(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>());
    return nullptr;
  }
  std::ifstream in(dir / "out.json");
  return nlohmann::json::parse(in);
}

std::vector<int> Pixels(const cv::Mat& grey) {
  std::vector<int> pixels;
  for (int row = 0; row < grey.rows; ++row) {
    for (int col = 0; col < grey.cols; ++col) pixels.push_back(grey.at<std::uint8_t>(row, col));
  }
  return pixels;
}

/// Pillow's frames of `png` are `frames`, pixel for pixel; what Pillow read goes to `decoded` (null without
/// Pillow: then the test fails under CI and is skipped elsewhere).
void ExpectPillowFrames(const std::string& png, const std::vector<cv::Mat>& frames, nlohmann::json& decoded) {
  std::string why;
  decoded = DecodeWithPillow(png, why);
  if (decoded.is_null()) {
    if (slamsweep::testing::RunningInCi()) FAIL() << why;
    GTEST_SKIP() << why;
  }
  ASSERT_EQ(decoded["frames"], frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(decoded["pixels"][i].get<std::vector<int>>(), Pixels(frames[i])) << "frame " << i;
  }
}

void ExpectPillowFrames(const std::string& png, const std::vector<cv::Mat>& frames) {
  nlohmann::json decoded;
  ExpectPillowFrames(png, frames, decoded);
}

TEST(CompactPngTest, GreyPngReadsBackAsTheSameValuesWithOpenCv) {
  const cv::Mat map = Stage(5);
  const std::string png = EncodeCompactGreyPng(map);
  const std::vector<std::uint8_t> bytes(png.begin(), png.end());
  const cv::Mat decoded = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  ASSERT_EQ(decoded.type(), CV_8UC1);
  EXPECT_EQ(cv::countNonZero(decoded != map), 0);
  // A map of runs of three values: far smaller than its PGM (one byte a cell).
  EXPECT_LT(png.size(), map.total() / 4);
}

TEST(CompactPngTest, AnimationDecodesToEveryFrameWithItsTiming) {
  std::vector<cv::Mat> frames;
  for (int step = 0; step < 6; ++step) frames.push_back(Stage(step));
  frames.push_back(Stage(5));  // a stage where nothing changed
  const std::string png = EncodeAnimatedGreyPng(frames, AnimatedPngTiming{15, 150});
  // Viewers without APNG support show the first frame: the file is a PNG OpenCV reads as frame 0.
  const std::vector<std::uint8_t> bytes(png.begin(), png.end());
  const cv::Mat first = cv::imdecode(bytes, cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(first.empty());
  EXPECT_EQ(cv::countNonZero(first != frames.front()), 0);

  nlohmann::json decoded;
  ExpectPillowFrames(png, frames, decoded);
  if (decoded.is_null() || HasFatalFailure()) return;
  EXPECT_EQ(decoded["width"], 70);
  EXPECT_EQ(decoded["height"], 40);
  EXPECT_EQ(decoded["loop"], 0);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(decoded["durations_ms"][i], i + 1 == frames.size() ? 1500 : 150) << "frame " << i;
  }
}

TEST(CompactPngTest, AnUnchangedPartIsNotStoredAgain) {
  // A robot driving along a 100 x 600 corridor: each of 12 stages sees the next 50 columns, walls at
  // scattered cells.
  std::vector<cv::Mat> frames;
  cv::Mat map(100, 600, CV_8UC1, cv::Scalar(205));
  for (int stage = 0; stage < 12; ++stage) {
    for (int row = 0; row < map.rows; ++row) {
      for (int col = 50 * stage; col < 50 * stage + 50; ++col) {
        map.at<std::uint8_t>(row, col) = (row * 7919 + col * 104729) % 13 == 0 ? 0 : 254;
      }
    }
    frames.push_back(map.clone());
  }
  std::size_t separate = 0;
  for (const cv::Mat& frame : frames) separate += EncodeCompactGreyPng(frame).size();
  // Less than half of the stages as separate PNG files (each of which holds every earlier stage again).
  EXPECT_LT(2 * EncodeAnimatedGreyPng(frames).size(), separate);
}

TEST(CompactPngTest, UnchangedPixelsInsideTheChangedRectangleAreNotStoredAgain) {
  // A map of scattered walls; the next stage changes one cell at each of two opposite corners, so the
  // rectangle that changed is the whole map but two of its pixels are new.
  cv::Mat map(300, 300, CV_8UC1, cv::Scalar(254));
  std::uint32_t state = 12345;  // a linear congruential generator: cells no deflate finds a pattern in
  for (int row = 0; row < map.rows; ++row) {
    for (int col = 0; col < map.cols; ++col) {
      state = state * 1664525u + 1013904223u;
      const std::uint32_t draw = state >> 24;
      if (draw < 40) map.at<std::uint8_t>(row, col) = 0;
      if (draw >= 40 && draw < 90) map.at<std::uint8_t>(row, col) = 205;
    }
  }
  cv::Mat later = map.clone();
  later.at<std::uint8_t>(0, 0) = 205;
  later.at<std::uint8_t>(299, 299) = 205;
  const std::size_t one_frame = EncodeAnimatedGreyPng({map}).size();
  const std::string two = EncodeAnimatedGreyPng({map, later});
  // The second frame costs a small fraction of the first (stored whole it would cost about as much).
  EXPECT_LT(two.size(), one_frame + one_frame / 10);
  ExpectPillowFrames(two, {map, later});
}

TEST(CompactPngTest, AFigureOfFewColoursReadsBackAsTheSamePixelsFromAPalettePng) {
  // A drawn figure: white ground, a grey grid, an anti-aliased blue line (a ramp of 40 blues).
  cv::Mat figure(120, 200, CV_8UC3, cv::Scalar(255, 255, 255));
  for (int col = 0; col < figure.cols; col += 20) figure.col(col).setTo(cv::Scalar(160, 160, 160));
  for (int col = 0; col < figure.cols; ++col) {
    figure.at<cv::Vec3b>(60 + col / 10, col) = cv::Vec3b(static_cast<std::uint8_t>(178 + col % 40), 114, 0);
  }
  const std::optional<std::string> png = EncodePalettePng(figure);
  ASSERT_TRUE(png.has_value());
  EXPECT_EQ(static_cast<unsigned char>((*png)[25]), 3u);  // IHDR colour type: palette
  const std::vector<std::uint8_t> bytes(png->begin(), png->end());
  const cv::Mat decoded = cv::imdecode(bytes, cv::IMREAD_COLOR);
  ASSERT_EQ(decoded.size(), figure.size());
  cv::Mat difference;
  cv::absdiff(decoded, figure, difference);
  EXPECT_EQ(cv::countNonZero(difference.reshape(1)), 0);
  // Two colours: one bit a pixel.
  cv::Mat two(8, 8, CV_8UC3, cv::Scalar(255, 255, 255));
  two.at<cv::Vec3b>(3, 3) = cv::Vec3b(0, 0, 0);
  const std::optional<std::string> small = EncodePalettePng(two);
  ASSERT_TRUE(small.has_value());
  EXPECT_EQ(static_cast<unsigned char>((*small)[24]), 1u);  // IHDR bit depth
  const std::vector<std::uint8_t> small_bytes(small->begin(), small->end());
  EXPECT_EQ(cv::imdecode(small_bytes, cv::IMREAD_COLOR).at<cv::Vec3b>(3, 3), cv::Vec3b(0, 0, 0));
}

TEST(CompactPngTest, MoreThan256ColoursAreNotAPalettePng) {
  cv::Mat ramp(1, 257, CV_8UC3);
  for (int col = 0; col < 257; ++col)
    ramp.at<cv::Vec3b>(0, col) = cv::Vec3b(static_cast<std::uint8_t>(col % 256), col / 256, 0);
  EXPECT_FALSE(EncodePalettePng(ramp).has_value());
  EXPECT_TRUE(EncodePalettePng(ramp.colRange(0, 256)).has_value());
  EXPECT_THROW(EncodePalettePng(cv::Mat(3, 3, CV_8UC1)), InputError);
}

TEST(CompactPngTest, BadFramesAreRefused) {
  EXPECT_THROW(EncodeAnimatedGreyPng({}), InputError);
  EXPECT_THROW(EncodeAnimatedGreyPng({Stage(0), cv::Mat(3, 3, CV_8UC1, cv::Scalar(0))}), InputError);
  EXPECT_THROW(EncodeCompactGreyPng(cv::Mat(3, 3, CV_16UC1)), InputError);
}

TEST(CompactPngTest, EveryGreyLevelSurvivesAnAnimation) {
  cv::Mat many(16, 16, CV_8UC1);
  for (int i = 0; i < 256; ++i) many.at<std::uint8_t>(i / 16, i % 16) = static_cast<std::uint8_t>(i);
  cv::Mat later = many.clone();
  later(cv::Rect(3, 4, 5, 6)).setTo(7);
  ExpectPillowFrames(EncodeAnimatedGreyPng({many, later}), {many, later});
}

}  // namespace
}  // namespace slamsweep::evaluator
