// The libpng codec against OpenCV's imgcodecs, the reader and writer slamsweep used before: every
// PNG colour type decodes to the pixels imdecode(IMREAD_UNCHANGED) gives (in R, G, B order), and the
// encoder writes the bytes imencode(".png") writes. The test PNGs are written with libpng's own
// writer here, so that palettes, transparency, low bit depths and interlacing are covered too.
#include "evaluator/formats/map/png_image.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <png.h>
#include <zlib.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "tests/evaluator/formats/map/map_test_helpers.h"

namespace slamsweep::evaluator {
namespace {

using map_test::InputErrorOf;
using ::testing::HasSubstr;

/// How a test PNG is written: IHDR fields, an optional palette and tRNS chunk, and the packed rows.
struct PngSpec {
  int width = 0;
  int height = 0;
  int bit_depth = 8;
  int color_type = PNG_COLOR_TYPE_GRAY;
  int interlace = PNG_INTERLACE_NONE;
  std::vector<png_color> palette{};
  std::vector<png_byte> palette_alpha{};       // tRNS of a palette image
  std::optional<png_color_16> trans_colour{};  // tRNS of a grey or RGB image
  std::vector<std::vector<png_byte>> rows{};   // packed as the IHDR says
};

void AppendBytes(png_structp png, png_bytep data, png_size_t count) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), count);
}

std::string WritePng(PngSpec spec) {
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png)) != 0) {
    png_destroy_write_struct(&png, &info);
    ADD_FAILURE() << "libpng could not write the test image";
    return {};
  }
  png_set_write_fn(png, &out, AppendBytes, nullptr);
  png_set_IHDR(png, info, static_cast<png_uint_32>(spec.width), static_cast<png_uint_32>(spec.height), spec.bit_depth,
               spec.color_type, spec.interlace, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (!spec.palette.empty()) png_set_PLTE(png, info, spec.palette.data(), static_cast<int>(spec.palette.size()));
  if (!spec.palette_alpha.empty()) {
    png_set_tRNS(png, info, spec.palette_alpha.data(), static_cast<int>(spec.palette_alpha.size()), nullptr);
  }
  if (spec.trans_colour) png_set_tRNS(png, info, nullptr, 1, &*spec.trans_colour);
  png_write_info(png, info);
  std::vector<png_bytep> rows;
  for (auto& row : spec.rows) rows.push_back(row.data());
  png_write_image(png, rows.data());
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return out;
}

/// OpenCV's decoding, turned from B, G, R(, A) into R, G, B(, A) as slamsweep delivers it.
cv::Mat OpenCvRgb(const std::string& bytes) {
  const cv::Mat buffer(1, static_cast<int>(bytes.size()), CV_8UC1, const_cast<char*>(bytes.data()));
  cv::Mat decoded = cv::imdecode(buffer, cv::IMREAD_UNCHANGED);
  if (decoded.channels() == 3) cv::cvtColor(decoded, decoded, cv::COLOR_BGR2RGB);
  if (decoded.channels() == 4) cv::cvtColor(decoded, decoded, cv::COLOR_BGRA2RGBA);
  return decoded;
}

void ExpectSamePixels(const cv::Mat& actual, const cv::Mat& expected) {
  ASSERT_FALSE(expected.empty());
  ASSERT_EQ(actual.type(), expected.type());
  ASSERT_EQ(actual.size(), expected.size());
  EXPECT_EQ(cv::norm(actual, expected, cv::NORM_INF), 0.0);
}

std::vector<std::vector<png_byte>> RandomRows(int height, std::size_t row_bytes, unsigned seed) {
  std::mt19937 random(seed);
  std::vector<std::vector<png_byte>> rows(static_cast<std::size_t>(height), std::vector<png_byte>(row_bytes));
  for (auto& row : rows) {
    for (png_byte& byte : row) byte = static_cast<png_byte>(random() & 0xff);
  }
  return rows;
}

std::vector<png_color> Palette(int size) {
  std::vector<png_color> palette;
  for (int i = 0; i < size; ++i) {
    palette.push_back({static_cast<png_byte>(i * 7), static_cast<png_byte>(255 - i), static_cast<png_byte>(i * 3)});
  }
  return palette;
}

TEST(PngImageTest, EveryColourTypeDecodesAsOpenCvDoes) {
  std::vector<PngSpec> specs;
  for (int depth : {1, 2, 4, 8}) {
    PngSpec grey{.width = 13, .height = 5, .bit_depth = depth, .color_type = PNG_COLOR_TYPE_GRAY};
    grey.rows = RandomRows(5, (13 * static_cast<std::size_t>(depth) + 7) / 8, 10u + static_cast<unsigned>(depth));
    specs.push_back(grey);
  }
  PngSpec grey_trans{.width = 9, .height = 4, .color_type = PNG_COLOR_TYPE_GRAY};
  grey_trans.rows = RandomRows(4, 9, 2);
  grey_trans.trans_colour = png_color_16{0, 0, 0, 0, grey_trans.rows[0][0]};
  specs.push_back(grey_trans);
  PngSpec grey_alpha{.width = 7, .height = 3, .color_type = PNG_COLOR_TYPE_GRAY_ALPHA};
  grey_alpha.rows = RandomRows(3, 14, 3);
  specs.push_back(grey_alpha);
  PngSpec rgb{.width = 11, .height = 6, .color_type = PNG_COLOR_TYPE_RGB};
  rgb.rows = RandomRows(6, 33, 4);
  specs.push_back(rgb);
  PngSpec rgb_trans = rgb;
  rgb_trans.trans_colour = png_color_16{0, rgb.rows[1][0], rgb.rows[1][1], rgb.rows[1][2], 0};
  specs.push_back(rgb_trans);
  PngSpec rgba{.width = 5, .height = 5, .color_type = PNG_COLOR_TYPE_RGB_ALPHA};
  rgba.rows = RandomRows(5, 20, 5);
  specs.push_back(rgba);
  for (int depth : {2, 8}) {
    PngSpec palette{.width = 10, .height = 4, .bit_depth = depth, .color_type = PNG_COLOR_TYPE_PALETTE};
    palette.palette = Palette(1 << depth);
    palette.rows = RandomRows(4, (10 * static_cast<std::size_t>(depth) + 7) / 8, 6u + static_cast<unsigned>(depth));
    specs.push_back(palette);
    palette.palette_alpha = {0, 128, 255};
    specs.push_back(palette);
  }
  PngSpec interlaced = rgb;
  interlaced.interlace = PNG_INTERLACE_ADAM7;
  specs.push_back(interlaced);

  for (std::size_t i = 0; i < specs.size(); ++i) {
    SCOPED_TRACE("test image " + std::to_string(i) + ", colour type " + std::to_string(specs[i].color_type) +
                 ", depth " + std::to_string(specs[i].bit_depth));
    const std::string bytes = WritePng(specs[i]);
    ExpectSamePixels(DecodePng(bytes, "test.png"), OpenCvRgb(bytes));
  }
}

TEST(PngImageTest, EncodesTheBytesOpenCvWrites) {
  std::mt19937 random(7);
  for (const int type : {CV_8UC1, CV_8UC3, CV_8UC4}) {
    for (const cv::Size size : {cv::Size(1, 1), cv::Size(37, 19), cv::Size(256, 3)}) {
      cv::Mat image(size, type);
      cv::randu(image, 0, 256);
      // Runs of equal values as in maps, where the run-length strategy matters.
      image.rowRange(0, (size.height + 1) / 2).setTo(cv::Scalar::all(205));
      std::vector<unsigned char> expected;
      ASSERT_TRUE(cv::imencode(".png", image, expected));
      const std::string actual = EncodePngBytes(image);
      EXPECT_EQ(actual, std::string(expected.begin(), expected.end()))
          << "type " << type << " size " << size.width << "x" << size.height;
    }
  }
}

TEST(PngImageTest, CorruptDataNamesTheFileAndLibpngsReason) {
  PngSpec rgb{.width = 8, .height = 8, .color_type = PNG_COLOR_TYPE_RGB};
  rgb.rows = RandomRows(8, 24, 9);
  std::string bytes = WritePng(rgb);
  const std::size_t idat = bytes.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  bytes[idat + 6] = static_cast<char>(bytes[idat + 6] ^ 0x55);  // damages the compressed pixel data
  const std::string message = InputErrorOf([&] { DecodePng(bytes, "broken.png"); });
  EXPECT_THAT(message, HasSubstr("broken.png"));
  EXPECT_THAT(message, HasSubstr("not a readable image"));
  EXPECT_THAT(message, HasSubstr("IDAT"));  // libpng's reason names the damaged chunk
}

TEST(PngImageTest, AHeaderClaimingMorePixelsThanTheFileCanHoldIsRefusedBeforeAllocating) {
  PngSpec grey{.width = 4, .height = 4};
  grey.rows = RandomRows(4, 4, 3);
  std::string bytes = WritePng(grey);
  // IHDR (after the 8-byte signature and the chunk's length) says 100000 x 100000: 10 GB of pixels from a
  // file of a hundred bytes. The chunk's CRC is made to match, so only the claim is wrong.
  const std::size_t ihdr = bytes.find("IHDR");
  ASSERT_NE(ihdr, std::string::npos);
  for (std::size_t field : {ihdr + 4, ihdr + 8}) bytes.replace(field, 4, std::string("\x00\x01\x86\xa0", 4));
  const uLong crc = crc32(0, reinterpret_cast<const Bytef*>(bytes.data() + ihdr), 17);
  for (int i = 0; i < 4; ++i) bytes[ihdr + 17 + i] = static_cast<char>((crc >> (24 - 8 * i)) & 0xff);
  const std::string message = InputErrorOf([&] { DecodePng(bytes, "huge.png"); });
  EXPECT_THAT(message, HasSubstr("huge.png"));
  EXPECT_THAT(message, HasSubstr("claims 100000 x 100000 pixels"));
}

TEST(PngImageTest, SixteenBitSamplesAreRefused) {
  PngSpec deep{.width = 2, .height = 2, .bit_depth = 16, .color_type = PNG_COLOR_TYPE_GRAY};
  deep.rows = RandomRows(2, 4, 1);
  EXPECT_THAT(InputErrorOf([&] { DecodePng(WritePng(deep), "deep.png"); }), HasSubstr("16-bit samples"));
}

TEST(PngImageTest, GreyPaletteDecodesToTheSameGreyLevelsAtTheSmallestDepth) {
  std::mt19937 random(11);
  // Two, three (a trinary stage map), four, sixteen and 200 levels; odd widths end rows mid-byte,
  // and 803 columns take the sixty-four-pixel steps of the two-bit packer and its tail.
  const std::vector<std::vector<std::uint8_t>> level_sets = {
      {0, 254},
      {0, 205, 254},
      {1, 2, 205, 254},
      {0, 17, 34, 51, 68, 85, 102, 119, 136, 153, 170, 187, 204, 221, 238, 255},
      {}};
  const std::vector<int> expected_depths = {1, 2, 2, 4, 8};
  for (std::size_t set = 0; set < level_sets.size(); ++set) {
    for (const cv::Size size : {cv::Size(1, 1), cv::Size(37, 19), cv::Size(803, 5)}) {
      cv::Mat grey(size, CV_8UC1);
      for (int row = 0; row < grey.rows; ++row) {
        for (int col = 0; col < grey.cols; ++col) {
          const std::vector<std::uint8_t>& levels = level_sets[set];
          grey.at<std::uint8_t>(row, col) =
              levels.empty() ? static_cast<std::uint8_t>(random() % 200) : levels[random() % levels.size()];
        }
      }
      const std::string bytes = EncodeGreyPalettePng(grey);
      // OpenCV's reader, independent of this codec, gives the grey values back (as B = G = R).
      cv::Mat read_back = OpenCvRgb(bytes);
      ASSERT_EQ(read_back.type(), CV_8UC3);
      cv::Mat channels[3];
      cv::split(read_back, channels);
      for (const cv::Mat& channel : channels) ExpectSamePixels(channel, grey);
      ExpectSamePixels(DecodePng(bytes, "palette.png"), read_back);
      if (size.area() > 256) {
        EXPECT_EQ(static_cast<int>(bytes[24]), expected_depths[set]) << "IHDR bit depth";
      }
    }
  }
}

TEST(PngImageTest, EncoderRefusesWhatPngCannotHold) {
  EXPECT_THROW(EncodePngBytes(cv::Mat(2, 2, CV_16UC1, cv::Scalar(1))), InputError);
  EXPECT_THROW(EncodePngBytes(cv::Mat(2, 2, CV_8UC2, cv::Scalar(1, 2))), InputError);
  EXPECT_THROW(EncodePngBytes(cv::Mat()), InputError);
  EXPECT_THROW(EncodeGreyPalettePng(cv::Mat(2, 2, CV_8UC3, cv::Scalar(1, 2, 3))), InputError);
}

}  // namespace
}  // namespace slamsweep::evaluator
