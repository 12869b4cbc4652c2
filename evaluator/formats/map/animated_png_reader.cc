#include "evaluator/formats/map/animated_png_reader.h"

#include <libdeflate.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <utility>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/png_signature.h"

namespace slamsweep::evaluator::inline formats::inline map {
namespace {

/// A canvas or frame is at most this many pixels: a header can claim any size.
constexpr double kMaxPixels = 16384.0 * 16384.0;

std::uint32_t U32(std::string_view bytes, std::size_t at) {
  return (std::uint32_t{static_cast<std::uint8_t>(bytes[at])} << 24) |
         (std::uint32_t{static_cast<std::uint8_t>(bytes[at + 1])} << 16) |
         (std::uint32_t{static_cast<std::uint8_t>(bytes[at + 2])} << 8) |
         std::uint32_t{static_cast<std::uint8_t>(bytes[at + 3])};
}

std::uint16_t U16(std::string_view bytes, std::size_t at) {
  return static_cast<std::uint16_t>((static_cast<std::uint8_t>(bytes[at]) << 8) |
                                    static_cast<std::uint8_t>(bytes[at + 1]));
}

std::uint8_t Paeth(int a, int b, int c) {
  const int p = a + b - c;
  const int pa = std::abs(p - a);
  const int pb = std::abs(p - b);
  const int pc = std::abs(p - c);
  if (pa <= pb && pa <= pc) return static_cast<std::uint8_t>(a);
  return static_cast<std::uint8_t>(pb <= pc ? b : c);
}

struct FreeDecompressor {
  void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
};

}  // namespace

AnimatedGreyPngReader::AnimatedGreyPngReader(std::string bytes, std::string source)
    : bytes_(std::move(bytes)), source_(std::move(source)) {
  const auto fail = [&](const std::string& message) { throw InputError(source_ + ": " + message); };
  const std::string_view data(bytes_);
  if (!data.starts_with(kPngSignature)) fail("not a PNG file (no PNG signature)");
  bool header_seen = false;
  bool animated = false;
  bool frames_begun = false;  // an fcTL came: IDAT belongs to the animation only after one
  std::uint32_t declared_frames = 0;
  std::size_t palette_entries = 0;
  std::string_view palette;
  std::string_view transparency;
  std::vector<std::string_view> still_image;
  bool ended = false;
  for (std::size_t at = kPngSignature.size(); !ended;) {
    if (at + 12 > data.size()) fail("truncated (the PNG ends without IEND)");
    const std::uint32_t length = U32(data, at);
    if (length > data.size() - at - 12) fail("truncated chunk at byte " + std::to_string(at));
    const std::string_view type = data.substr(at + 4, 4);
    const std::string_view body = data.substr(at + 8, length);
    const std::uint32_t crc = U32(data, at + 8 + length);
    if (libdeflate_crc32(0, data.data() + at + 4, length + 4) != crc) {
      fail("chunk " + std::string(type) + " at byte " + std::to_string(at) + " has a wrong CRC");
    }
    at += 12 + length;
    if (!header_seen && type != "IHDR") fail("the first chunk is " + std::string(type) + ", not IHDR");
    if (type == "IHDR") {
      if (length != 13) fail("IHDR of " + std::to_string(length) + " bytes");
      header_seen = true;
      const std::uint32_t width = U32(body, 0);
      const std::uint32_t height = U32(body, 4);
      bit_depth_ = static_cast<std::uint8_t>(body[8]);
      colour_type_ = static_cast<std::uint8_t>(body[9]);
      if (width == 0 || height == 0 || static_cast<double>(width) * height > kMaxPixels) {
        fail("image of " + std::to_string(width) + " x " + std::to_string(height) + " pixels");
      }
      if (colour_type_ != 0 && colour_type_ != 3) {
        fail("colour type " + std::to_string(colour_type_) + "; expected grey (0) or a palette (3)");
      }
      if (bit_depth_ != 1 && bit_depth_ != 2 && bit_depth_ != 4 && bit_depth_ != 8) {
        fail("bit depth " + std::to_string(bit_depth_) + "; expected 1, 2, 4 or 8");
      }
      if (body[10] != 0 || body[11] != 0) fail("unknown compression or filter method");
      if (body[12] != 0) fail("interlaced; expected a non-interlaced PNG");
      size_ = cv::Size(static_cast<int>(width), static_cast<int>(height));
    } else if (type == "PLTE") {
      if (length % 3 != 0 || length == 0 || length / 3 > 256) fail("PLTE of " + std::to_string(length) + " bytes");
      palette = body;
      palette_entries = length / 3;
    } else if (type == "tRNS") {
      transparency = body;
    } else if (type == "acTL") {
      if (length != 8) fail("acTL of " + std::to_string(length) + " bytes");
      animated = true;
      declared_frames = U32(body, 0);
    } else if (type == "fcTL") {
      if (length != 26) fail("fcTL of " + std::to_string(length) + " bytes");
      Frame frame;
      const std::uint32_t w = U32(body, 4);
      const std::uint32_t h = U32(body, 8);
      const std::uint32_t x = U32(body, 12);
      const std::uint32_t y = U32(body, 16);
      if (w == 0 || h == 0 || x > static_cast<std::uint32_t>(size_.width) - w ||
          y > static_cast<std::uint32_t>(size_.height) - h || w > static_cast<std::uint32_t>(size_.width) ||
          h > static_cast<std::uint32_t>(size_.height)) {
        fail("frame " + std::to_string(frames_.size()) + " lies outside the image");
      }
      frame.rect = cv::Rect(static_cast<int>(x), static_cast<int>(y), static_cast<int>(w), static_cast<int>(h));
      const int numerator = U16(body, 20);
      const int denominator = U16(body, 22) == 0 ? 100 : U16(body, 22);
      frame.delay_cs = static_cast<int>(std::lround(100.0 * numerator / denominator));
      frame.dispose = static_cast<std::uint8_t>(body[24]);
      frame.blend = static_cast<std::uint8_t>(body[25]);
      if (frame.dispose > 2 || frame.blend > 1) fail("frame " + std::to_string(frames_.size()) + ": unknown operation");
      frames_.push_back(frame);
      frames_begun = true;
    } else if (type == "IDAT") {
      if (frames_begun && frames_.size() == 1) frames_.back().data.push_back(body);
      still_image.push_back(body);
    } else if (type == "fdAT") {
      if (length < 4 || frames_.empty()) fail("fdAT before any fcTL");
      frames_.back().data.push_back(body.substr(4));
    } else if (type == "IEND") {
      ended = true;
    } else if ((static_cast<unsigned char>(type[0]) & 0x20) == 0) {
      fail("unknown critical chunk " + std::string(type));
    }
  }
  if (still_image.empty()) fail("no IDAT (no image data)");
  if (animated && frames_.empty()) fail("an animation without frames (no fcTL)");
  if (!animated) {
    frames_.clear();
    Frame whole;
    whole.rect = cv::Rect(0, 0, size_.width, size_.height);
    whole.data = still_image;
    frames_.push_back(whole);
  } else if (frames_.size() != declared_frames) {
    fail("acTL declares " + std::to_string(declared_frames) + " frames, the file holds " +
         std::to_string(frames_.size()));
  }
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    if (frames_[i].data.empty()) fail("frame " + std::to_string(i) + " has no image data");
  }

  // The grey value and opacity of every sample value.
  const std::size_t samples = std::size_t{1} << bit_depth_;
  grey_of_.assign(samples, 0);
  opaque_of_.assign(samples, true);
  if (colour_type_ == 3) {
    if (palette.empty()) fail("a palette image without PLTE");
    for (std::size_t i = 0; i < palette_entries; ++i) {
      const auto r = static_cast<std::uint8_t>(palette[3 * i]);
      if (r != static_cast<std::uint8_t>(palette[3 * i + 1]) || r != static_cast<std::uint8_t>(palette[3 * i + 2])) {
        fail("palette entry " + std::to_string(i) + " is not grey");
      }
      if (i < samples) grey_of_[i] = r;
    }
    // Indices past the palette are an error wherever they occur (DecodeFrame).
    for (std::size_t i = palette_entries; i < samples; ++i) opaque_of_[i] = false;
    if (transparency.size() > palette_entries) fail("tRNS longer than the palette");
    for (std::size_t i = 0; i < transparency.size(); ++i) {
      const auto alpha = static_cast<std::uint8_t>(transparency[i]);
      if (alpha != 0 && alpha != 255) fail("palette entry " + std::to_string(i) + " is partly transparent");
      opaque_of_[i] = alpha == 255;
    }
    palette_entries_ = palette_entries;
  } else {
    for (std::size_t v = 0; v < samples; ++v) {
      grey_of_[v] = static_cast<std::uint8_t>(v * 255 / (samples - 1));
    }
    if (!transparency.empty()) {
      if (transparency.size() != 2) fail("tRNS of a grey image of " + std::to_string(transparency.size()) + " bytes");
      const std::uint16_t transparent = U16(transparency, 0);
      if (transparent < samples) opaque_of_[transparent] = false;
    }
    palette_entries_ = samples;
  }
}

std::vector<int> AnimatedGreyPngReader::DelaysCs() const {
  std::vector<int> delays;
  for (const Frame& frame : frames_) delays.push_back(frame.delay_cs);
  return delays;
}

cv::Mat AnimatedGreyPngReader::DecodeFrame(const Frame& frame, cv::Mat& opaque) const {
  const auto width = static_cast<std::size_t>(frame.rect.width);
  const auto height = static_cast<std::size_t>(frame.rect.height);
  const std::size_t row_bytes = (width * static_cast<std::size_t>(bit_depth_) + 7) / 8;
  std::string compressed;
  for (const std::string_view piece : frame.data) compressed.append(piece);
  std::string raw(height * (row_bytes + 1), '\0');
  const std::unique_ptr<libdeflate_decompressor, FreeDecompressor> decompressor(libdeflate_alloc_decompressor());
  if (!decompressor) throw InputError(source_ + ": out of memory");
  std::size_t produced = 0;
  const libdeflate_result result = libdeflate_zlib_decompress(decompressor.get(), compressed.data(), compressed.size(),
                                                              raw.data(), raw.size(), &produced);
  if (result != LIBDEFLATE_SUCCESS || produced != raw.size()) {
    throw InputError(source_ + ": image data that does not inflate to " + std::to_string(raw.size()) + " bytes");
  }
  // Undo each row's filter (one byte per pixel step: every depth here is at most 8 bits).
  auto* rows = reinterpret_cast<std::uint8_t*>(raw.data());
  for (std::size_t row = 0; row < height; ++row) {
    std::uint8_t* line = rows + row * (row_bytes + 1);
    const std::uint8_t filter = line[0];
    std::uint8_t* cur = line + 1;
    const std::uint8_t* up = row > 0 ? rows + (row - 1) * (row_bytes + 1) + 1 : nullptr;
    for (std::size_t i = 0; i < row_bytes; ++i) {
      const int a = i > 0 ? cur[i - 1] : 0;
      const int b = up != nullptr ? up[i] : 0;
      const int c = i > 0 && up != nullptr ? up[i - 1] : 0;
      switch (filter) {
        case 0:
          break;
        case 1:
          cur[i] = static_cast<std::uint8_t>(cur[i] + a);
          break;
        case 2:
          cur[i] = static_cast<std::uint8_t>(cur[i] + b);
          break;
        case 3:
          cur[i] = static_cast<std::uint8_t>(cur[i] + (a + b) / 2);
          break;
        case 4:
          cur[i] = static_cast<std::uint8_t>(cur[i] + Paeth(a, b, c));
          break;
        default:
          throw InputError(source_ + ": unknown filter type " + std::to_string(filter) + " in row " +
                           std::to_string(row));
      }
    }
  }
  cv::Mat grey(frame.rect.size(), CV_8UC1);
  opaque.create(frame.rect.size(), CV_8UC1);
  const int per_byte = 8 / bit_depth_;
  const unsigned mask = (1u << bit_depth_) - 1;
  for (std::size_t row = 0; row < height; ++row) {
    const std::uint8_t* line = rows + row * (row_bytes + 1) + 1;
    auto* out = grey.ptr<std::uint8_t>(static_cast<int>(row));
    auto* alpha = opaque.ptr<std::uint8_t>(static_cast<int>(row));
    for (std::size_t col = 0; col < width; ++col) {
      const int shift = bit_depth_ * (per_byte - 1 - static_cast<int>(col % static_cast<std::size_t>(per_byte)));
      const unsigned sample = (line[col / static_cast<std::size_t>(per_byte)] >> shift) & mask;
      if (sample >= palette_entries_) {
        throw InputError(source_ + ": palette index " + std::to_string(sample) + " past the palette's " +
                         std::to_string(palette_entries_) + " entries");
      }
      out[col] = grey_of_[sample];
      alpha[col] = opaque_of_[sample] ? 255 : 0;
    }
  }
  return grey;
}

void AnimatedGreyPngReader::ForEachFrame(const std::function<void(std::size_t, const cv::Mat&)>& visit) const {
  cv::Mat canvas(size_, CV_8UC1, cv::Scalar(0));
  cv::Mat opaque;
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    const Frame& frame = frames_[i];
    cv::Mat region = canvas(frame.rect);
    // Dispose "previous" restores what was under the frame; on the first frame it means "background".
    const std::uint8_t dispose = i == 0 && frame.dispose == 2 ? 1 : frame.dispose;
    const cv::Mat before = dispose == 2 ? region.clone() : cv::Mat();
    const cv::Mat grey = DecodeFrame(frame, opaque);
    if (frame.blend == 0) {
      // Source: the frame replaces the region, its transparent pixels included (transparent black).
      region.setTo(cv::Scalar(0));
    }
    grey.copyTo(region, opaque);
    visit(i, canvas);
    if (dispose == 1) region.setTo(cv::Scalar(0));
    if (dispose == 2) before.copyTo(region);
  }
}

AnimatedGreyPngReader OpenAnimatedGreyPng(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open()) throw InputError(path.string() + ": cannot be opened");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(path.string() + ": cannot be read");
  return AnimatedGreyPngReader(std::move(bytes), path.string());
}

std::vector<cv::Mat> DecodeAnimatedGreyPng(std::string bytes, std::string source) {
  const AnimatedGreyPngReader reader(std::move(bytes), std::move(source));
  std::vector<cv::Mat> frames;
  frames.reserve(reader.FrameCount());
  reader.ForEachFrame([&](std::size_t, const cv::Mat& canvas) { frames.push_back(canvas.clone()); });
  return frames;
}

}  // namespace slamsweep::evaluator::inline formats::inline map
