#include "report/images/thumbnail.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "evaluator/core/input_error.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

using ::testing::HasSubstr;

TEST(WriteThumbnailTest, CropsToTheKnownAreaAndShrinks) {
  testing::TempDir dir;
  // 1000 x 600 map, unknown except a 400 x 200 known block at (300, 200).
  cv::Mat map(600, 1000, CV_8UC1, cv::Scalar(205));
  map(cv::Rect(300, 200, 400, 200)).setTo(254);
  map(cv::Rect(300, 200, 400, 4)).setTo(0);
  ASSERT_TRUE(cv::imwrite((dir / "map.pgm").string(), map));
  WriteThumbnail(dir / "map.pgm", dir / "thumb.png", 120);
  const cv::Mat thumb = cv::imread((dir / "thumb.png").string(), cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(thumb.empty());
  EXPECT_EQ(thumb.type(), CV_8UC1);
  // Margin 4 % of 1000 = 40: crop 480 x 280, shrunk by 120 / 480 to 120 x 70.
  EXPECT_EQ(thumb.cols, 120);
  EXPECT_EQ(thumb.rows, 70);
  EXPECT_EQ(thumb.at<uchar>(0, 0), 205);    // the margin is unknown
  EXPECT_EQ(thumb.at<uchar>(40, 60), 254);  // inside the free block
}

TEST(WriteThumbnailTest, NeverEnlargesAndKeepsAnAllUnknownMapWhole) {
  testing::TempDir dir;
  ASSERT_TRUE(cv::imwrite((dir / "small.png").string(), cv::Mat(30, 50, CV_8UC1, cv::Scalar(205))));
  WriteThumbnail(dir / "small.png", dir / "thumb.png", 200);
  const cv::Mat thumb = cv::imread((dir / "thumb.png").string(), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(thumb.size(), cv::Size(50, 30));
}

TEST(WriteThumbnailTest, ColourMapsBecomeGrey) {
  testing::TempDir dir;
  ASSERT_TRUE(cv::imwrite((dir / "rgb.png").string(), cv::Mat(10, 10, CV_8UC3, cv::Scalar(254, 254, 254))));
  WriteThumbnail(dir / "rgb.png", dir / "thumb.png", 200);
  const cv::Mat thumb = cv::imread((dir / "thumb.png").string(), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(thumb.type(), CV_8UC1);
  EXPECT_EQ(thumb.at<uchar>(5, 5), 254);
}

TEST(WriteThumbnailTest, BadInputIsAnInputErrorNamingIt) {
  testing::TempDir dir;
  try {
    WriteThumbnail(dir / "missing.pgm", dir / "t.png", 100);
    FAIL();
  } catch (const evaluator::InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("missing.pgm"));
  }
  testing::WriteFile(dir / "junk.pgm", "P5\n10 10\n255\nshort");
  EXPECT_THROW(WriteThumbnail(dir / "junk.pgm", dir / "t.png", 100), evaluator::InputError);
  ASSERT_TRUE(cv::imwrite((dir / "ok.png").string(), cv::Mat(10, 10, CV_8UC1, cv::Scalar(0))));
  EXPECT_THROW(WriteThumbnail(dir / "ok.png", dir / "no-such-dir" / "t.png", 100), evaluator::InputError);
  try {
    WriteThumbnail(dir / "ok.png", dir / "t.png", 0);
    FAIL();
  } catch (const evaluator::InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("max_side_px"));
  }
}

}  // namespace
}  // namespace slamsweep::report
