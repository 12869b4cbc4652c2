#include "evaluator/formats/map/pnm_image.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/evaluator/formats/map/map_test_helpers.h"

namespace slamsweep::evaluator {
namespace {

using map_test::InputErrorOf;
using ::testing::HasSubstr;

TEST(PnmImageTest, DecodesBinaryPgmRowByRow) {
  const cv::Mat image = DecodePnm(map_test::Pgm(3, 2, {0, 1, 2, 250, 254, 255}), "a.pgm");
  ASSERT_EQ(image.type(), CV_8UC1);
  ASSERT_EQ(image.cols, 3);
  ASSERT_EQ(image.rows, 2);
  EXPECT_EQ(image.at<uchar>(0, 0), 0);
  EXPECT_EQ(image.at<uchar>(0, 2), 2);
  EXPECT_EQ(image.at<uchar>(1, 0), 250);
  EXPECT_EQ(image.at<uchar>(1, 2), 255);
}

TEST(PnmImageTest, HeaderCommentsAsMapSaverWritesThem) {
  // map_saver puts "# CREATOR: ..." between the magic number and the size.
  std::string bytes = "P5\n# CREATOR: map_saver.cpp 0.050 m/pix\n2 1\n255\n";
  bytes += static_cast<char>(205);
  bytes += static_cast<char>(0);
  const cv::Mat image = DecodePnm(bytes, "m.pgm");
  EXPECT_EQ(image.at<uchar>(0, 0), 205);
  EXPECT_EQ(image.at<uchar>(0, 1), 0);
}

TEST(PnmImageTest, AsciiPgmAndSmallMaxvalScaleLikeSdlImage) {
  // SDL_image stretches maxval 15 to 255 with integer arithmetic: 7 * 255 / 15 = 119.
  const cv::Mat image = DecodePnm("P2\n# comment\n3 1\n15\n0 7 15\n", "a.pgm");
  EXPECT_EQ(image.at<uchar>(0, 0), 0);
  EXPECT_EQ(image.at<uchar>(0, 1), 119);
  EXPECT_EQ(image.at<uchar>(0, 2), 255);
}

TEST(PnmImageTest, PpmDecodesToRgbOrder) {
  std::string bytes = "P6\n1 1\n255\n";
  bytes += {static_cast<char>(10), static_cast<char>(20), static_cast<char>(30)};
  const cv::Mat image = DecodePnm(bytes, "c.ppm");
  ASSERT_EQ(image.type(), CV_8UC3);
  EXPECT_EQ(image.at<cv::Vec3b>(0, 0), cv::Vec3b(10, 20, 30));
}

TEST(PnmImageTest, TruncatedPixelDataNamesTheFileAndSizes) {
  const std::string full = map_test::Pgm(4, 4, std::vector<std::uint8_t>(16, 254));
  const std::string message = InputErrorOf([&] { DecodePnm(full.substr(0, full.size() - 3), "cut.pgm"); });
  EXPECT_THAT(message, HasSubstr("cut.pgm"));
  EXPECT_THAT(message, HasSubstr("truncated"));
  EXPECT_THAT(message, HasSubstr("16 samples"));
  EXPECT_THAT(message, HasSubstr("13 bytes"));
}

TEST(PnmImageTest, TruncatedHeaderAndAsciiData) {
  EXPECT_THAT(InputErrorOf([] { DecodePnm("P5\n12", "h.pgm"); }), HasSubstr("before the height"));
  EXPECT_THAT(InputErrorOf([] { DecodePnm("P2\n2 2\n255\n1 2 3", "a.pgm"); }), HasSubstr("truncated"));
}

TEST(PnmImageTest, SixteenBitIsRejectedWithItsMaxval) {
  const std::string message = InputErrorOf([] { DecodePnm("P5\n1 1\n65535\n\x01\x02", "deep.pgm"); });
  EXPECT_THAT(message, HasSubstr("deep.pgm"));
  EXPECT_THAT(message, HasSubstr("16-bit"));
  EXPECT_THAT(message, HasSubstr("65535"));
}

TEST(PnmImageTest, RejectsBitmapsBadSizesAndSamplesAboveMaxval) {
  EXPECT_THAT(InputErrorOf([] { DecodePnm("P4\n8 1\n\xff", "b.pbm"); }), HasSubstr("PBM"));
  EXPECT_THAT(InputErrorOf([] { DecodePnm("P5\n0 3\n255\n", "z.pgm"); }), HasSubstr("positive size"));
  EXPECT_THAT(InputErrorOf([] { DecodePnm("P5\nx 3\n255\n", "x.pgm"); }), HasSubstr("width"));
  EXPECT_THAT(InputErrorOf([] { DecodePnm("P2\n2 1\n100\n50 101\n", "m.pgm"); }), HasSubstr("above maxval 100"));
  EXPECT_THAT(InputErrorOf([] { DecodePnm("P5\n99999 99999\n255\n", "big.pgm"); }), HasSubstr("too large"));
  // Announced but absent pixel data is reported without allocating 1.6 GB for it.
  EXPECT_THAT(InputErrorOf([] { DecodePnm("P5\n40000 40000\n255\n", "big.pgm"); }), HasSubstr("truncated"));
}

TEST(PnmImageTest, EncodePgmWritesMapSaverLayoutAndDecodesBack) {
  cv::Mat grey(2, 3, CV_8UC1);
  for (int i = 0; i < 6; ++i) grey.at<uchar>(i / 3, i % 3) = static_cast<uchar>(i * 50);
  const std::string bytes = EncodePgm(grey, "CREATOR: test");
  EXPECT_EQ(bytes.substr(0, bytes.size() - 6), "P5\n# CREATOR: test\n3 2\n255\n");
  const cv::Mat back = DecodePnm(bytes, "x.pgm");
  EXPECT_EQ(cv::countNonZero(back != grey), 0);
}

}  // namespace
}  // namespace slamsweep::evaluator
