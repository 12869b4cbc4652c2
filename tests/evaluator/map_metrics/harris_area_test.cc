#include "evaluator/map_metrics/harris_area.h"

#include <gtest/gtest.h>

#include <cstring>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace slamsweep::evaluator {
namespace {

// cv::cornerHarris on the call area itself, cut to `kept`: what HarrisResponseOfArea must equal.
cv::Mat Direct(const cv::Mat& image, cv::Rect call_area, cv::Rect kept, int aperture, double k) {
  cv::Mat response;
  cv::cornerHarris(image(call_area), response, 2, aperture, k, cv::BORDER_DEFAULT);
  return response(kept - call_area.tl()).clone();
}

// Bit for bit, +0 and -0 told apart.
void ExpectSameBits(const cv::Mat& actual, const cv::Mat& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (int r = 0; r < actual.rows; ++r) {
    for (int c = 0; c < actual.cols; ++c) {
      std::uint32_t a = 0, e = 0;
      std::memcpy(&a, &actual.at<float>(r, c), sizeof a);
      std::memcpy(&e, &expected.at<float>(r, c), sizeof e);
      ASSERT_EQ(a, e) << "at row " << r << ", col " << c << ": " << actual.at<float>(r, c) << " vs "
                      << expected.at<float>(r, c);
    }
  }
}

// Images whose values span many orders of magnitude (so that the double running sums round), are
// mostly zero with scattered structure, or zero but for a few blobs; call areas inside the image and at its edges, of
// sizes whose cell counts leave every remainder modulo 8, each kept rectangle strictly inside or touching them.
TEST(HarrisAreaTest, EqualsCornerHarrisOnTheCallAreaBitForBit) {
  cv::RNG rng(4242);
  for (int trial = 0; trial < 400; ++trial) {
    SCOPED_TRACE(trial);
    const int kind = trial % 4;
    const int rows = rng.uniform(8, 90);
    const int cols = rng.uniform(8, kind == 3 ? 200 : 90);
    cv::Mat image(rows, cols, CV_32FC1);
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < cols; ++c) {
        float v = 0.0f;
        if (kind == 0) v = static_cast<float>(rng.uniform(-1.0, 1.0) * std::pow(10.0, rng.uniform(-8.0, 8.0)));
        if (kind == 1) v = static_cast<float>(rng.uniform(-2.0, 2.0));
        if (kind == 2 && rng.uniform(0, 10) == 0) v = static_cast<float>(rng.uniform(-3.0, 3.0));
        image.at<float>(r, c) = v;
      }
    }
    // Zero but for a few blobs of values over many magnitudes: long runs of zero derivatives between
    // structure, entered with running sums that are zero or that kept a rounding residue.
    for (int blob = 0; kind == 3 && blob < 4; ++blob) {
      const int r0 = rng.uniform(0, rows), c0 = rng.uniform(0, cols);
      const int r1 = std::min(rows, r0 + rng.uniform(1, 6)), c1 = std::min(cols, c0 + rng.uniform(1, 12));
      for (int r = r0; r < r1; ++r) {
        for (int c = c0; c < c1; ++c) {
          image.at<float>(r, c) = static_cast<float>(rng.uniform(-1.0, 1.0) * std::pow(10.0, rng.uniform(-8.0, 8.0)));
        }
      }
    }
    const int x0 = rng.uniform(0, cols - 2), y0 = rng.uniform(0, rows - 2);
    const cv::Rect call(x0, y0, rng.uniform(2, cols - x0 + 1), rng.uniform(2, rows - y0 + 1));
    const int kx = call.x + rng.uniform(0, call.width), ky = call.y + rng.uniform(0, call.height);
    const cv::Rect kept(kx, ky, rng.uniform(1, call.x + call.width - kx + 1),
                        rng.uniform(1, call.y + call.height - ky + 1));
    const int aperture = (trial % 4 == 3) ? 5 : 3;
    const double k = trial % 5 == 4 ? 0.06 : 0.04;
    cv::Mat actual(kept.size(), CV_32FC1, cv::Scalar(7.0f));
    SCOPED_TRACE(::testing::Message() << "call " << call << " kept " << kept << " image " << image.size());
    HarrisResponseOfArea(image, call, kept, aperture, k, actual);
    ExpectSameBits(actual, Direct(image, call, kept, aperture, k));
  }
}

TEST(HarrisAreaTest, SupportsOnlyTheTwoByTwoBlockOnTwoCellsOrMore) {
  EXPECT_TRUE(HarrisAreaSupported(2, {2, 2}));
  EXPECT_FALSE(HarrisAreaSupported(3, {50, 50}));
  EXPECT_FALSE(HarrisAreaSupported(2, {1, 50}));
}

}  // namespace
}  // namespace slamsweep::evaluator
