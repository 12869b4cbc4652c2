#include "evaluator/formats/map/animated_png_reader.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/compact_png.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using nlohmann::json;

std::string ReadBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Runs a Python helper (python3-pil); its stdout, or nullopt with `why`.
std::optional<std::string> RunPython(const std::string& script, const std::vector<std::string>& args,
                                     std::string& why) {
  slamsweep::testing::TempDir dir;
  std::string command = "/usr/bin/python3 '" + script + "'";
  for (const std::string& arg : args) command += " '" + arg + "'";
  command += " > '" + (dir / "out").string() + "' 2> '" + (dir / "err").string() + "'";
  if (std::system(command.c_str()) != 0) {
    why = "python3 with Pillow (apt-get install python3-pil) failed: " + ReadBytes(dir / "err");
    return std::nullopt;
  }
  return ReadBytes(dir / "out");
}

/// An APNG written by tests/.../apng_writer.py from `spec`, and its frames as Pillow composes them
/// (apng_frames.py): both independent of slamsweep's own writer. Null json when Python or Pillow is missing.
json WriteAndDecodeWithPillow(const json& spec, std::string& png, std::string& why) {
  slamsweep::testing::TempDir dir;
  slamsweep::testing::WriteFile(dir / "spec.json", spec.dump());
  if (!RunPython(SLAMSWEEP_APNG_WRITER, {(dir / "spec.json").string(), (dir / "out.png").string()}, why))
    return nullptr;
  png = ReadBytes(dir / "out.png");
  const std::optional<std::string> decoded = RunPython(SLAMSWEEP_APNG_READER, {(dir / "out.png").string()}, why);
  if (!decoded) return nullptr;
  return json::parse(*decoded);
}

std::vector<int> FramePixels(const cv::Mat& grey) {
  std::vector<int> pixels;
  for (int row = 0; row < grey.rows; ++row) {
    for (int col = 0; col < grey.cols; ++col) pixels.push_back(grey.at<std::uint8_t>(row, col));
  }
  return pixels;
}

/// Our reader's frames of the APNG that `spec` makes equal Pillow's, pixel for pixel.
void ExpectFramesAsPillowComposesThem(const json& spec) {
  std::string png;
  std::string why;
  const json expected = WriteAndDecodeWithPillow(spec, png, why);
  if (expected.is_null()) SLAMSWEEP_SKIP_OR_FAIL_IN_CI(why);
  const std::vector<cv::Mat> frames = DecodeAnimatedGreyPng(png, "pillow.png");
  ASSERT_EQ(frames.size(), expected["frames"].get<std::size_t>());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(frames[i].cols, expected["width"].get<int>());
    EXPECT_EQ(FramePixels(frames[i]), expected["pixels"][i].get<std::vector<int>>()) << "frame " << i;
  }
}

/// A growing map: stage `step` knows columns 0 .. 2 step + 1.
std::vector<int> GrowingStage(int step, int width, int height) {
  std::vector<int> pixels(static_cast<std::size_t>(width * height), 205);
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col <= std::min(width - 1, 2 * step + 1); ++col) {
      pixels[static_cast<std::size_t>(row * width + col)] = row == 0 || (col * 7 + row * 3) % 11 == 0 ? 0 : 254;
    }
  }
  return pixels;
}

json PillowSpec(const std::string& mode, int blend) {
  json frames = json::array();
  for (int step = 0; step < 6; ++step) frames.push_back(GrowingStage(step, 17, 9));
  frames.push_back(GrowingStage(5, 17, 9));  // nothing changed
  return {{"mode", mode}, {"width", 17}, {"height", 9}, {"blend", blend}, {"duration_ms", 150}, {"frames", frames}};
}

TEST(AnimatedGreyPngReaderTest, ReadsPillowsGreyAnimation) { ExpectFramesAsPillowComposesThem(PillowSpec("L", 0)); }

TEST(AnimatedGreyPngReaderTest, ReadsPillowsGreyAnimationBlendedOver) {
  ExpectFramesAsPillowComposesThem(PillowSpec("L", 1));
}

TEST(AnimatedGreyPngReaderTest, ReadsPillowsPaletteAnimation) { ExpectFramesAsPillowComposesThem(PillowSpec("P", 0)); }

TEST(AnimatedGreyPngReaderTest, FollowsEveryFilterDisposeAndBlendOperationAndTransparency) {
  // Written chunk by chunk (apng_writer.py "chunks"): 2-bit palette, each frame with another row filter;
  // frame 1 disposed to what was before it, frame 2 to transparent black; frame 4 blended over with a
  // transparent index.
  const json spec = {
      {"mode", "chunks"},
      {"width", 5},
      {"height", 3},
      {"bit_depth", 2},
      {"palette", {0, 205, 254, 100}},
      {"transparent", 3},
      {"frames",
       {{{"x", 0},
         {"y", 0},
         {"w", 5},
         {"h", 3},
         {"dispose", 0},
         {"blend", 0},
         {"filter", 4},
         {"indices", {1, 1, 1, 1, 1, 1, 2, 2, 1, 0, 1, 1, 1, 1, 1}}},
        {{"x", 1},
         {"y", 1},
         {"w", 2},
         {"h", 2},
         {"dispose", 2},
         {"blend", 0},
         {"filter", 3},
         {"indices", {0, 0, 2, 0}}},
        {{"x", 0}, {"y", 0}, {"w", 2}, {"h", 1}, {"dispose", 1}, {"blend", 0}, {"filter", 1}, {"indices", {0, 2}}},
        {{"x", 2},
         {"y", 0},
         {"w", 3},
         {"h", 3},
         {"dispose", 0},
         {"blend", 0},
         {"filter", 2},
         {"indices", {0, 0, 2, 2, 0, 2, 1, 1, 2}}},
        {{"x", 0},
         {"y", 0},
         {"w", 5},
         {"h", 3},
         {"dispose", 0},
         {"blend", 1},
         {"filter", 0},
         {"indices", {3, 3, 0, 3, 3, 3, 3, 3, 3, 2, 3, 3, 3, 3, 3}}}}}};
  ExpectFramesAsPillowComposesThem(spec);
}

TEST(AnimatedGreyPngReaderTest, ReadsBackEveryFrameOfTheStageAnimationsWeWrite) {
  // Stage maps that grow, a stage where nothing changed, and the same with every grey level in use (the
  // writer then has no transparent index and replaces rectangles whole).
  for (const bool all_levels : {false, true}) {
    std::vector<cv::Mat> frames;
    for (int step = 0; step < 5; ++step) {
      cv::Mat frame(40, 90, CV_8UC1, cv::Scalar(205));
      frame(cv::Rect(3, 3, 10 + 15 * step, 30)).setTo(254);
      frame(cv::Rect(3, 3, 10 + 15 * step, 2)).setTo(0);
      if (all_levels) {
        for (int level = 0; level < 256; ++level) frame.at<std::uint8_t>(35 + level / 90, level % 90) = level;
      }
      frames.push_back(frame);
    }
    frames.push_back(frames.back().clone());
    const AnimatedGreyPngReader reader(EncodeAnimatedGreyPng(frames, {15, 150}), "stages.png");
    EXPECT_EQ(reader.Size(), frames.front().size());
    EXPECT_EQ(reader.DelaysCs(), (std::vector<int>{15, 15, 15, 15, 15, 150}));
    std::size_t seen = 0;
    reader.ForEachFrame([&](std::size_t index, const cv::Mat& canvas) {
      EXPECT_EQ(cv::countNonZero(canvas != frames[index]), 0) << "frame " << index << " all levels " << all_levels;
      ++seen;
    });
    EXPECT_EQ(seen, frames.size());
  }
}

TEST(AnimatedGreyPngReaderTest, AStillPngIsOneFrame) {
  cv::Mat map(7, 9, CV_8UC1, cv::Scalar(205));
  map(cv::Rect(2, 2, 4, 3)).setTo(0);
  const std::vector<cv::Mat> frames = DecodeAnimatedGreyPng(EncodeCompactGreyPng(map), "map.png");
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(cv::countNonZero(frames[0] != map), 0);
}

TEST(AnimatedGreyPngReaderTest, WhatItCannotReadIsAnInputErrorNamingTheFile) {
  std::vector<cv::Mat> frames(2, cv::Mat(6, 6, CV_8UC1, cv::Scalar(205)));
  frames[1].at<std::uint8_t>(2, 2) = 0;
  const std::string good = EncodeAnimatedGreyPng(frames);
  const auto message_of = [](std::string bytes) {
    try {
      DecodeAnimatedGreyPng(std::move(bytes), "run/stages.png");
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message_of("GIF89a").find("run/stages.png: not a PNG"), std::string::npos);
  EXPECT_NE(message_of(good.substr(0, good.size() - 20)).find("run/stages.png: "), std::string::npos);
  std::string bad_crc = good;
  bad_crc[40] = static_cast<char>(bad_crc[40] ^ 0x01);
  EXPECT_NE(message_of(bad_crc).find("CRC"), std::string::npos);
  // A colour palette (its CRC made right again) is not a grey map.
  std::string colour = good;
  const std::size_t type = colour.find("PLTE");
  ASSERT_NE(type, std::string::npos);
  colour[type + 4] = static_cast<char>(colour[type + 4] ^ 0x10);
  const auto length = static_cast<std::size_t>(static_cast<std::uint8_t>(colour[type - 1]));
  const uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(colour.data() + type), static_cast<uInt>(length + 4));
  for (int i = 0; i < 4; ++i) colour[type + 4 + length + i] = static_cast<char>((crc >> (24 - 8 * i)) & 0xff);
  EXPECT_NE(message_of(colour).find("palette entry 0 is not grey"), std::string::npos) << message_of(colour);
}

}  // namespace
}  // namespace slamsweep::evaluator
