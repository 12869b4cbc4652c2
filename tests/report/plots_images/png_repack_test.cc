// RepackAsPalettePng against OpenCV's imgcodecs as the independent PNG reader and writer: the repacked
// figure holds the same pixels in fewer bytes, and files it cannot improve are left byte for byte.
#include "report/plots/png_repack.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

std::string FileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

unsigned ColourType(const std::filesystem::path& png) { return static_cast<unsigned char>(FileBytes(png).at(25)); }

// A figure-like image: white ground, a blue and an orange block (B, G, R as OpenCV stores them).
cv::Mat ThreeColours() {
  cv::Mat image(60, 80, CV_8UC3, cv::Scalar(255, 255, 255));
  image(cv::Rect(5, 5, 20, 30)).setTo(cv::Scalar(0xB2, 0x72, 0x00));
  image(cv::Rect(40, 20, 30, 10)).setTo(cv::Scalar(0x00, 0x5E, 0xD5));
  return image;
}

TEST(RepackAsPalettePngTest, AFigureOfFewColoursKeepsItsPixelsInAPalette) {
  testing::TempDir dir;
  const std::filesystem::path png = dir / "figure.png";
  const cv::Mat original = ThreeColours();
  ASSERT_TRUE(cv::imwrite(png.string(), original));
  const auto rgb_size = std::filesystem::file_size(png);
  ASSERT_EQ(ColourType(png), 2u);  // RGB as written
  RepackAsPalettePng(png);
  EXPECT_EQ(ColourType(png), 3u);
  EXPECT_LT(std::filesystem::file_size(png), rgb_size);
  const cv::Mat repacked = cv::imread(png.string(), cv::IMREAD_COLOR);
  ASSERT_EQ(repacked.size(), original.size());
  EXPECT_EQ(cv::norm(repacked, original, cv::NORM_INF), 0.0) << "the palette changed a pixel (channel order?)";
}

TEST(RepackAsPalettePngTest, MoreThan256ColoursAndUnreadableFilesAreLeftAsTheyAre) {
  testing::TempDir dir;
  const std::filesystem::path many = dir / "many.png";
  cv::Mat gradient(32, 32, CV_8UC3);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) gradient.at<cv::Vec3b>(y, x) = cv::Vec3b(x * 8, y * 8, (x + y) * 4);
  }
  ASSERT_TRUE(cv::imwrite(many.string(), gradient));
  const std::string many_before = FileBytes(many);
  RepackAsPalettePng(many);
  EXPECT_EQ(FileBytes(many), many_before);

  const std::filesystem::path broken = dir / "broken.png";
  std::ofstream(broken, std::ios::binary) << "\x89PNG\r\n\x1a\n truncated";
  const std::string broken_before = FileBytes(broken);
  RepackAsPalettePng(broken);
  EXPECT_EQ(FileBytes(broken), broken_before);
  EXPECT_FALSE(std::filesystem::exists(dir / "broken.png.repack"));
}

}  // namespace
}  // namespace slamsweep::report
