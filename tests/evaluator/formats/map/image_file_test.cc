#include "evaluator/formats/map/image_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/evaluator/formats/map/map_test_helpers.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using map_test::InputErrorOf;
using ::testing::HasSubstr;

TEST(ImageFileTest, GreyPngReadsAsOneChannel) {
  testing::TempDir dir;
  cv::Mat grey(2, 2, CV_8UC1, cv::Scalar(205));
  grey.at<uchar>(1, 0) = 0;
  map_test::WriteImage(dir / "g.png", grey);
  const cv::Mat image = ReadImageFile(dir / "g.png");
  ASSERT_EQ(image.type(), CV_8UC1);
  EXPECT_EQ(image.at<uchar>(0, 0), 205);
  EXPECT_EQ(image.at<uchar>(1, 0), 0);
}

TEST(ImageFileTest, ColourPngIsDeliveredInRgbaOrder) {
  testing::TempDir dir;
  map_test::WriteImage(dir / "c.png", map_test::RgbaRow({cv::Vec4b(10, 20, 30, 40)}));
  const cv::Mat image = ReadImageFile(dir / "c.png");
  ASSERT_EQ(image.type(), CV_8UC4);
  EXPECT_EQ(image.at<cv::Vec4b>(0, 0), cv::Vec4b(10, 20, 30, 40));

  map_test::WriteImage(dir / "rgb.png", map_test::RgbRow({cv::Vec3b(1, 2, 3)}));
  const cv::Mat rgb = ReadImageFile(dir / "rgb.png");
  ASSERT_EQ(rgb.type(), CV_8UC3);
  EXPECT_EQ(rgb.at<cv::Vec3b>(0, 0), cv::Vec3b(1, 2, 3));
}

TEST(ImageFileTest, SixteenBitPngIsRejected) {
  testing::TempDir dir;
  map_test::WriteImage(dir / "deep.png", cv::Mat(2, 2, CV_16UC1, cv::Scalar(1000)));
  const std::string message = InputErrorOf([&] { ReadImageFile(dir / "deep.png"); });
  EXPECT_THAT(message, HasSubstr("deep.png"));
  EXPECT_THAT(message, HasSubstr("16-bit"));
}

TEST(ImageFileTest, MissingEmptyNotAnImageAndTruncatedPng) {
  testing::TempDir dir;
  EXPECT_THAT(InputErrorOf([&] { ReadImageFile(dir / "none.png"); }), HasSubstr("no such image file"));
  testing::WriteFile(dir / "empty.pgm", "");
  EXPECT_THAT(InputErrorOf([&] { ReadImageFile(dir / "empty.pgm"); }), HasSubstr("empty file"));
  testing::WriteFile(dir / "text.png", "this is not an image\n");
  EXPECT_THAT(InputErrorOf([&] { ReadImageFile(dir / "text.png"); }), HasSubstr("not a readable image"));

  cv::Mat noise(64, 64, CV_8UC1);
  cv::randu(noise, 0, 256);
  map_test::WriteImage(dir / "full.png", noise);
  const std::string bytes = map_test::ReadAll(dir / "full.png");
  testing::WriteFile(dir / "cut.png", bytes.substr(0, bytes.size() / 2));
  const std::string message = InputErrorOf([&] { ReadImageFile(dir / "cut.png"); });
  EXPECT_THAT(message, HasSubstr("cut.png"));
  EXPECT_THAT(message, HasSubstr("truncated"));
}

TEST(ImageFileTest, OtherImageFormatsAreNamedAndRefused) {
  // slamsweep reads PGM and PNG maps (README); a BMP or JPEG map is named as such, not misread.
  testing::TempDir dir;
  map_test::WriteImage(dir / "map.bmp", cv::Mat(4, 4, CV_8UC1, cv::Scalar(254)));
  map_test::WriteImage(dir / "map.jpg", cv::Mat(4, 4, CV_8UC1, cv::Scalar(254)));
  const std::string bmp = InputErrorOf([&] { ReadImageFile(dir / "map.bmp"); });
  EXPECT_THAT(bmp, HasSubstr("map.bmp"));
  EXPECT_THAT(bmp, HasSubstr("a BMP image"));
  EXPECT_THAT(bmp, HasSubstr("PGM and PNG"));
  EXPECT_THAT(InputErrorOf([&] { ReadImageFile(dir / "map.jpg"); }), HasSubstr("a JPEG image"));
}

TEST(ImageFileTest, GreyReaderAcceptsGreySavedAsColourOnly) {
  testing::TempDir dir;
  map_test::WriteImage(dir / "grey_rgb.png", map_test::RgbRow({cv::Vec3b(7, 7, 7), cv::Vec3b(200, 200, 200)}));
  const cv::Mat grey = ReadGreyImageFile(dir / "grey_rgb.png");
  ASSERT_EQ(grey.type(), CV_8UC1);
  EXPECT_EQ(grey.at<uchar>(0, 0), 7);
  EXPECT_EQ(grey.at<uchar>(0, 1), 200);

  map_test::WriteImage(dir / "red.png", map_test::RgbRow({cv::Vec3b(7, 7, 7), cv::Vec3b(255, 0, 0)}));
  const std::string message = InputErrorOf([&] { ReadGreyImageFile(dir / "red.png"); });
  EXPECT_THAT(message, HasSubstr("red.png"));
  EXPECT_THAT(message, HasSubstr("column 1"));

  map_test::WriteImage(dir / "clear.png", map_test::RgbaRow({cv::Vec4b(9, 9, 9, 0)}));
  EXPECT_THAT(InputErrorOf([&] { ReadGreyImageFile(dir / "clear.png"); }), HasSubstr("opaque grey"));
}

TEST(ImageFileTest, WriteBinaryFileReportsAnUnwritablePath) {
  EXPECT_THAT(InputErrorOf([] { WriteBinaryFile("/nonexistent/slamsweep/x.pgm", "x"); }),
              HasSubstr("/nonexistent/slamsweep/x.pgm"));
}

}  // namespace
}  // namespace slamsweep::evaluator
