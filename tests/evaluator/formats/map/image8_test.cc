#include "evaluator/formats/map/image8.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/evaluator/formats/map/map_test_helpers.h"

namespace slamsweep::evaluator {
namespace {

using map_test::InputErrorOf;
using ::testing::HasSubstr;

TEST(Image8Test, FreeIsWhiteOccupiedIsBlackUnknownIsMarked) {
  OccupancyGrid grid(4, 1, 0.05);
  grid.at(0, 0) = 0.0f;  // free -> 255
  grid.at(0, 1) = 1.0f;  // occupied -> 0
  grid.at(0, 2) = 0.5f;  // 127.5 rounds half away from zero -> 128
  // grid.at(0, 3) stays unknown
  const cv::Mat image = ToImage8(grid, 205);
  ASSERT_EQ(image.type(), CV_8UC1);
  EXPECT_EQ(image.at<uchar>(0, 0), 255);
  EXPECT_EQ(image.at<uchar>(0, 1), 0);
  EXPECT_EQ(image.at<uchar>(0, 2), 128);
  EXPECT_EQ(image.at<uchar>(0, 3), 205);
}

TEST(Image8Test, RowZeroStaysTheTopRow) {
  OccupancyGrid grid(1, 2, 0.05);
  grid.at(0, 0) = 1.0f;
  grid.at(1, 0) = 0.0f;
  const cv::Mat image = ToImage8(grid, 127);
  EXPECT_EQ(image.at<uchar>(0, 0), 0);
  EXPECT_EQ(image.at<uchar>(1, 0), 255);
}

TEST(Image8Test, FromImage8IsTheInverseForEveryGreyLevel) {
  cv::Mat image(16, 16, CV_8UC1);
  for (int v = 0; v < 256; ++v) image.at<uchar>(v / 16, v % 16) = static_cast<uchar>(v);
  const OccupancyGrid grid = FromImage8(image, std::nullopt, 0.1, GridOrigin{1.0, 2.0, 0.0});
  EXPECT_EQ(grid.width, 16);
  EXPECT_EQ(grid.height, 16);
  EXPECT_DOUBLE_EQ(grid.resolution_m, 0.1);
  EXPECT_DOUBLE_EQ(grid.origin.x_m, 1.0);
  EXPECT_DOUBLE_EQ(grid.origin.y_m, 2.0);
  for (int v = 0; v < 256; ++v) {
    // Without an unknown value every cell is known, even the traditional 205 grey.
    EXPECT_FLOAT_EQ(grid.at(v / 16, v % 16), (255.0f - v) / 255.0f) << "grey level " << v;
  }
  const cv::Mat back = ToImage8(grid, 0);
  EXPECT_EQ(cv::countNonZero(back != image), 0);
}

TEST(Image8Test, OnlyTheGivenUnknownValueIsUnknown) {
  cv::Mat image(1, 3, CV_8UC1);
  image.at<uchar>(0, 0) = 205;
  image.at<uchar>(0, 1) = 204;
  image.at<uchar>(0, 2) = 127;
  const OccupancyGrid grid = FromImage8(image, 205, 0.05);
  EXPECT_TRUE(OccupancyGrid::IsUnknown(grid.at(0, 0)));
  EXPECT_FLOAT_EQ(grid.at(0, 1), 51.0f / 255.0f);
  EXPECT_FLOAT_EQ(grid.at(0, 2), 128.0f / 255.0f);
}

TEST(Image8Test, BadArgumentsAreInputErrors) {
  OccupancyGrid grid(2, 2, 0.05, {}, 0.0f);
  EXPECT_THAT(InputErrorOf([&] { ToImage8(grid, 256); }), HasSubstr("unknown_value"));
  grid.at(1, 0) = 1.5f;
  EXPECT_THAT(InputErrorOf([&] { ToImage8(grid, 205); }), HasSubstr("row 1, column 0"));
  grid.at(1, 0) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(ToImage8(grid, 205), InputError);
  grid.cells.pop_back();
  EXPECT_THAT(InputErrorOf([&] { ToImage8(grid, 205); }), HasSubstr("holds 3 values"));

  const cv::Mat colour(2, 2, CV_8UC3, cv::Scalar(0, 0, 0));
  EXPECT_THROW(FromImage8(colour, std::nullopt, 0.05), InputError);
  const cv::Mat grey(2, 2, CV_8UC1, cv::Scalar(0));
  EXPECT_THAT(InputErrorOf([&] { FromImage8(grey, -1, 0.05); }), HasSubstr("unknown_value"));
  EXPECT_THAT(InputErrorOf([&] { FromImage8(grey, std::nullopt, 0.0); }), HasSubstr("resolution"));
  EXPECT_THROW(FromImage8(grey, std::nullopt, std::nan("")), InputError);
}

}  // namespace
}  // namespace slamsweep::evaluator
