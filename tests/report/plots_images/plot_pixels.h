#pragma once

// What the plot tests share: skipping without gnuplot, and counting the pixels of a colour in a PNG.

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <opencv2/core.hpp>

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

}  // namespace slamsweep::testing
