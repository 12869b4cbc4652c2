#include "report/images/area_shrink.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace slamsweep::report {
namespace {

TEST(ShrunkSizeTest, LongerSideToTheLimitNeverEnlarged) {
  EXPECT_EQ(ShrunkSize({1000, 500}, 480), cv::Size(480, 240));
  EXPECT_EQ(ShrunkSize({300, 1000}, 480), cv::Size(144, 480));
  EXPECT_EQ(ShrunkSize({200, 100}, 480), cv::Size(200, 100));
  EXPECT_EQ(ShrunkSize({5000, 1}, 10), cv::Size(10, 1));
}

TEST(ShrinkByAreaTest, IntegerFactorAveragesBlocksExactly) {
  // 4 x 2 pixels -> 2 x 1: each output is the mean of a 2 x 2 block (hand computed).
  const cv::Mat image = (cv::Mat_<uchar>(2, 4) << 0, 4, 100, 100, 8, 12, 200, 200);
  const cv::Mat shrunk = ShrinkByArea(image, {2, 1});
  ASSERT_EQ(shrunk.size(), cv::Size(2, 1));
  EXPECT_EQ(shrunk.at<uchar>(0, 0), 6);    // (0 + 4 + 8 + 12) / 4
  EXPECT_EQ(shrunk.at<uchar>(0, 1), 150);  // (100 + 100 + 200 + 200) / 4
}

TEST(ShrinkByAreaTest, NonIntegerFactorStaysCloseToOneStepAreaAveraging) {
  cv::Mat image(1000, 1000, CV_8UC1, cv::Scalar(205));
  cv::circle(image, {500, 500}, 400, cv::Scalar(254), cv::FILLED);
  for (int w = 100; w < 1000; w += 150) {
    image.col(w).setTo(0);
    image.row(w).setTo(0);
  }
  cv::Mat expected;
  cv::resize(image, expected, {480, 480}, 0, 0, cv::INTER_AREA);
  const cv::Mat shrunk = ShrinkByArea(image, {480, 480});
  ASSERT_EQ(shrunk.size(), expected.size());
  cv::Mat difference;
  cv::absdiff(shrunk, expected, difference);
  EXPECT_LT(cv::mean(difference)[0], 2.0);
  // Every one-pixel wall is still visible: each wall row of the result is darker than free space.
  for (int w = 100; w < 1000; w += 150) {
    const int row = static_cast<int>(w * 0.48);
    double darkest = 255;
    for (int r = std::max(0, row - 1); r <= std::min(479, row + 1); ++r)
      darkest = std::min<double>(darkest, shrunk.at<uchar>(r, 240));
    EXPECT_LT(darkest, 200) << "wall at row " << w;
  }
}

TEST(ShrinkByAreaTest, RaggedEdgesKeepTheirLastColumn) {
  // 1001 columns, the last one black: after shrinking to 100 columns it still darkens the edge.
  cv::Mat image(10, 1001, CV_8UC1, cv::Scalar(255));
  image.col(1000).setTo(0);
  const cv::Mat shrunk = ShrinkByArea(image, {100, 1});
  EXPECT_LT(shrunk.at<uchar>(0, 99), 255);
}

TEST(ShrinkToFitTest, SameImageWhenItFits) {
  const cv::Mat image(30, 40, CV_8UC1, cv::Scalar(7));
  EXPECT_EQ(ShrinkToFit(image, 40).data, image.data);
}

}  // namespace
}  // namespace slamsweep::report
