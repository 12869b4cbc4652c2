#include "report/images/image_header.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

TEST(PeekImageSizeTest, PngAndPgm) {
  testing::TempDir dir;
  const cv::Mat image(37, 91, CV_8UC1, cv::Scalar(205));
  ASSERT_TRUE(cv::imwrite((dir / "a.png").string(), image));
  ASSERT_TRUE(cv::imwrite((dir / "a.pgm").string(), image));
  EXPECT_EQ(PeekImageSize(dir / "a.png"), cv::Size(91, 37));
  EXPECT_EQ(PeekImageSize(dir / "a.pgm"), cv::Size(91, 37));
}

TEST(PeekImageSizeTest, PgmHeaderWithComment) {
  testing::TempDir dir;
  testing::WriteFile(dir / "c.pgm", std::string("P5\n# CREATOR: map_saver\n4 3\n255\n") + std::string(12, 'x'));
  EXPECT_EQ(PeekImageSize(dir / "c.pgm"), cv::Size(4, 3));
}

TEST(PeekImageSizeTest, UnknownOrBrokenFilesGiveNothing) {
  testing::TempDir dir;
  testing::WriteFile(dir / "t.png", "not an image at all, just text");
  testing::WriteFile(dir / "short.png", "\x89PNG");
  testing::WriteFile(dir / "bad.pgm", "P5\n-4 x\n");
  EXPECT_FALSE(PeekImageSize(dir / "t.png"));
  EXPECT_FALSE(PeekImageSize(dir / "short.png"));
  EXPECT_FALSE(PeekImageSize(dir / "bad.pgm"));
  EXPECT_FALSE(PeekImageSize(dir / "missing.png"));
}

}  // namespace
}  // namespace slamsweep::report
