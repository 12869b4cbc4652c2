#pragma once

// What the plot tests share: skipping without gnuplot, reading a PNG while keeping a copy for a person to
// look at, and counting the pixels of a colour in it. Its includers define SLAMSWEEP_ARTIFACT_DIR
// (tests/report/plots_images/CMakeLists.txt).

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/support/shared_data.h"

/// Skips the test when gnuplot is not installed (fails under CI, where it must be), naming it.
#define REQUIRE_GNUPLOT()                                                                        \
  if (!std::filesystem::exists("/usr/bin/gnuplot")) {                                            \
    if (::slamsweep::testing::RunningInCi()) FAIL() << "/usr/bin/gnuplot missing (gnuplot-nox)"; \
    GTEST_SKIP() << "/usr/bin/gnuplot missing: install gnuplot-nox";                             \
  }

namespace slamsweep::testing {

/// Pixels of exactly the colour 0xRRGGBB in a BGR image.
inline int CountColour(const cv::Mat& bgr, std::uint32_t rgb) {
  const cv::Vec3b wanted(rgb & 0xFF, (rgb >> 8) & 0xFF, (rgb >> 16) & 0xFF);
  int count = 0;
  for (int r = 0; r < bgr.rows; ++r) {
    for (int c = 0; c < bgr.cols; ++c) count += bgr.at<cv::Vec3b>(r, c) == wanted ? 1 : 0;
  }
  return count;
}

/// Reads the PNG (BGR) and keeps a copy as a test artefact (build/tests/report/plots_images/figures/).
inline cv::Mat ReadAndKeep(const std::filesystem::path& png) {
  const std::filesystem::path kept = std::filesystem::path(SLAMSWEEP_ARTIFACT_DIR) / "figures";
  std::filesystem::create_directories(kept);
  std::filesystem::copy_file(png, kept / png.filename(), std::filesystem::copy_options::overwrite_existing);
  const cv::Mat image = cv::imread(png.string(), cv::IMREAD_COLOR);
  EXPECT_FALSE(image.empty()) << png;
  return image;
}

}  // namespace slamsweep::testing
