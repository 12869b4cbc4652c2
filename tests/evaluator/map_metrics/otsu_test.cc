#include "evaluator/map_metrics/otsu.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace slamsweep::evaluator {
namespace {

Histogram256 HistogramOf(const cv::Mat& image) {
  Histogram256 h{};
  for (int r = 0; r < image.rows; ++r) {
    for (int c = 0; c < image.cols; ++c) ++h[image.at<uchar>(r, c)];
  }
  return h;
}

int OpenCvOtsu(const cv::Mat& image) {
  cv::Mat binary;
  return static_cast<int>(cv::threshold(image, binary, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU));
}

TEST(OtsuTest, TwoValuesAreSeparated) {
  // Every t in [10, 199] separates {10} from {200} perfectly (all have the same variance up
  // to rounding); any other t does not separate them at all.
  Histogram256 h{};
  h[10] = 30;
  h[200] = 70;
  EXPECT_GE(OtsuThreshold(h), 10);
  EXPECT_LT(OtsuThreshold(h), 200);
}

TEST(OtsuTest, ThreeClustersSplitBetweenTheOuterOnes) {
  // Masses 1/2 at 0, 1/4 at 100, 1/4 at 200. Between-class variance q1 q2 (mu1 - mu2)^2:
  // splitting after 0 gives 0.5 * 0.5 * (0 - 150)^2 = 5625, after 100 gives
  // 0.75 * 0.25 * (33.3 - 200)^2 = 5208, so the split lies in [0, 100).
  Histogram256 h{};
  h[0] = 200;
  h[100] = 100;
  h[200] = 100;
  const int t = OtsuThreshold(h);
  EXPECT_GE(t, 0);
  EXPECT_LT(t, 100);
}

TEST(OtsuTest, DegenerateHistogramsGiveZero) {
  EXPECT_EQ(OtsuThreshold(Histogram256{}), 0);
  Histogram256 h{};
  h[128] = 1000;
  EXPECT_EQ(OtsuThreshold(h), 0);
}

TEST(OtsuTest, AgreesWithOpenCvOnRandomImages) {
  cv::RNG rng(7);
  for (int trial = 0; trial < 400; ++trial) {
    cv::Mat image(rng.uniform(1, 60), rng.uniform(1, 60), CV_8UC1);
    // Mixtures of a few spikes and noise, where near-ties between thresholds happen.
    const int mode = trial % 3;
    if (mode == 0) {
      rng.fill(image, cv::RNG::UNIFORM, 0, 256);
    } else if (mode == 1) {
      rng.fill(image, cv::RNG::NORMAL, rng.uniform(20, 230), rng.uniform(1, 60));
    } else {
      const int values[3] = {rng.uniform(0, 256), rng.uniform(0, 256), rng.uniform(0, 256)};
      for (int i = 0; i < static_cast<int>(image.total()); ++i)
        image.data[i] = static_cast<uchar>(values[rng.uniform(0, 3)]);
    }
    EXPECT_EQ(OtsuThreshold(HistogramOf(image)), OpenCvOtsu(image)) << "trial " << trial;
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
