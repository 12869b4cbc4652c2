#include "evaluator/formats/map/compact_png.h"

#include <libdeflate.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <unordered_map>
#include <string_view>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/png_signature.h"

namespace slamsweep::evaluator::inline formats::inline map {
namespace {

// libdeflate level 6: a third of level 9's time for maps and stage animations 8-12 % larger (bench/scale).
constexpr int kDeflateLevel = 6;

void PutU32(std::string& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>((value >> shift) & 0xff));
}

void PutU16(std::string& out, std::uint16_t value) {
  out.push_back(static_cast<char>(value >> 8));
  out.push_back(static_cast<char>(value & 0xff));
}

// A chunk: length, type, data, CRC-32 of type and data (PNG specification, section 5.3).
void PutChunk(std::string& out, std::string_view type, std::string_view data) {
  PutU32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t crc_start = out.size();
  out.append(type);
  out.append(data);
  const std::uint32_t crc = libdeflate_crc32(0, out.data() + crc_start, out.size() - crc_start);
  PutU32(out, crc);
}

struct FreeCompressor {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};
using Compressor = std::unique_ptr<libdeflate_compressor, FreeCompressor>;

// One compressor for every stream of a file: allocating it is most of the cost of a small frame.
Compressor NewCompressor() {
  Compressor compressor(libdeflate_alloc_compressor(kDeflateLevel));
  if (!compressor) throw InputError("PNG encoding: out of memory");
  return compressor;
}

std::string Zlib(libdeflate_compressor* compressor, const std::string& raw) {
  std::string out(libdeflate_zlib_compress_bound(compressor, raw.size()), '\0');
  const std::size_t size = libdeflate_zlib_compress(compressor, raw.data(), raw.size(), out.data(), out.size());
  if (size == 0) throw InputError("PNG encoding: compression failed");
  out.resize(size);
  return out;
}

std::string Header(int width, int height, int bit_depth, int colour_type) {
  std::string ihdr;
  PutU32(ihdr, static_cast<std::uint32_t>(width));
  PutU32(ihdr, static_cast<std::uint32_t>(height));
  ihdr.push_back(static_cast<char>(bit_depth));
  ihdr.push_back(static_cast<char>(colour_type));
  ihdr.append(3, '\0');  // deflate, adaptive filtering, no interlace
  return ihdr;
}

// Scanlines of `rect` of a grey image, each with filter byte 0 (None), as `index_of` maps its grey levels,
// packed at BitDepth bits per pixel (PNG's order: the first pixel in the high bits). With `before`, a pixel
// equal to before's is `unchanged` (the transparent index) instead.
// Scanlines of a whole 8-bit grey image as they are, each with filter byte 0 (None).
std::string GreyRows(const cv::Mat& grey) {
  const auto width = static_cast<std::size_t>(grey.cols);
  std::string raw(static_cast<std::size_t>(grey.rows) * (width + 1), '\0');
  for (int row = 0; row < grey.rows; ++row) {
    std::memcpy(raw.data() + static_cast<std::size_t>(row) * (width + 1) + 1, grey.ptr<std::uint8_t>(row), width);
  }
  return raw;
}

template <int BitDepth>
std::string PackedRows(const cv::Mat& grey, const cv::Rect& rect, const std::array<std::uint8_t, 256>& index_of,
                       const cv::Mat* before, std::uint8_t unchanged) {
  constexpr int kPerByte = 8 / BitDepth;
  const auto width = static_cast<std::size_t>(rect.width);
  const std::size_t row_bytes = (width * BitDepth + 7) / 8;
  std::string raw(static_cast<std::size_t>(rect.height) * (row_bytes + 1), '\0');
  for (int row = 0; row < rect.height; ++row) {
    auto* out = reinterpret_cast<std::uint8_t*>(raw.data()) + static_cast<std::size_t>(row) * (row_bytes + 1) + 1;
    const std::uint8_t* pixels = grey.ptr<std::uint8_t>(rect.y + row) + rect.x;
    const std::uint8_t* old = before != nullptr ? before->ptr<std::uint8_t>(rect.y + row) + rect.x : nullptr;
    std::size_t col = 0;
    for (std::size_t byte = 0; byte < row_bytes; ++byte) {
      unsigned packed = 0;
      for (int j = 0; j < kPerByte; ++j, ++col) {
        unsigned index = 0;
        if (col < width) index = old != nullptr && old[col] == pixels[col] ? unchanged : index_of[pixels[col]];
        packed = (packed << BitDepth) | index;
      }
      out[byte] = static_cast<std::uint8_t>(packed);
    }
  }
  return raw;
}

std::string PackedRows(int bit_depth, const cv::Mat& grey, const cv::Rect& rect,
                       const std::array<std::uint8_t, 256>& index_of, const cv::Mat* before = nullptr,
                       std::uint8_t unchanged = 0) {
  switch (bit_depth) {
    case 1:
      return PackedRows<1>(grey, rect, index_of, before, unchanged);
    case 2:
      return PackedRows<2>(grey, rect, index_of, before, unchanged);
    case 4:
      return PackedRows<4>(grey, rect, index_of, before, unchanged);
    default:
      return PackedRows<8>(grey, rect, index_of, before, unchanged);
  }
}

void CheckGrey(const cv::Mat& image, const char* what) {
  if (image.type() != CV_8UC1 || image.empty()) {
    throw InputError(std::string("PNG encoding: expected non-empty 8-bit single-channel images, got another ") + what);
  }
}

// fcTL: sequence number, size, offset, delay (in 1/100 s), dispose none, blend source (the frame replaces
// the pixels under it) or over (its transparent pixels leave them as they were).
std::string FrameControl(std::uint32_t sequence, const cv::Rect& rect, int delay_cs, bool blend_over) {
  std::string fctl;
  PutU32(fctl, sequence);
  PutU32(fctl, static_cast<std::uint32_t>(rect.width));
  PutU32(fctl, static_cast<std::uint32_t>(rect.height));
  PutU32(fctl, static_cast<std::uint32_t>(rect.x));
  PutU32(fctl, static_cast<std::uint32_t>(rect.y));
  PutU16(fctl, static_cast<std::uint16_t>(delay_cs));
  PutU16(fctl, 100);
  fctl.push_back('\0');
  fctl.push_back(blend_over ? '\1' : '\0');
  return fctl;
}

}  // namespace

cv::Rect ChangedRect(const cv::Mat& before, const cv::Mat& after) {
  int top = after.rows;
  int bottom = -1;
  int left = after.cols;
  int right = -1;
  const auto width = static_cast<std::size_t>(after.cols);
  for (int row = 0; row < after.rows; ++row) {
    const std::uint8_t* a = before.ptr<std::uint8_t>(row);
    const std::uint8_t* b = after.ptr<std::uint8_t>(row);
    if (std::memcmp(a, b, width) == 0) continue;
    int first = 0;
    while (a[first] == b[first]) ++first;
    int last = after.cols - 1;
    while (a[last] == b[last]) --last;
    top = std::min(top, row);
    bottom = row;
    left = std::min(left, first);
    right = std::max(right, last);
  }
  if (bottom < 0) return {};
  return {left, top, right - left + 1, bottom - top + 1};
}

std::string EncodeCompactGreyPng(const cv::Mat& grey) {
  CheckGrey(grey, "image");
  std::string png(kPngSignature);
  PutChunk(png, "IHDR", Header(grey.cols, grey.rows, 8, 0));
  PutChunk(png, "IDAT", Zlib(NewCompressor().get(), GreyRows(grey)));
  PutChunk(png, "IEND", "");
  return png;
}

std::optional<std::string> EncodePalettePng(const cv::Mat& bgr) {
  if (bgr.type() != CV_8UC3 || bgr.empty()) {
    throw InputError("PNG encoding: expected a non-empty 8-bit BGR image for a palette PNG");
  }
  // Each pixel's palette index, colours numbered as they first appear (runs of one colour skip the lookup).
  cv::Mat indices(bgr.size(), CV_8UC1);
  std::unordered_map<std::uint32_t, std::uint8_t> index_of_colour;
  std::string palette;
  std::uint32_t last_colour = 0xFFFFFFFF;
  std::uint8_t last_index = 0;
  for (int row = 0; row < bgr.rows; ++row) {
    const auto* pixels = bgr.ptr<cv::Vec3b>(row);
    auto* out = indices.ptr<std::uint8_t>(row);
    for (int col = 0; col < bgr.cols; ++col) {
      const cv::Vec3b& p = pixels[col];
      const std::uint32_t colour = (std::uint32_t{p[2]} << 16) | (std::uint32_t{p[1]} << 8) | p[0];
      if (colour != last_colour) {
        const auto [it, added] = index_of_colour.try_emplace(colour, static_cast<std::uint8_t>(palette.size() / 3));
        if (added) {
          if (index_of_colour.size() > 256) return std::nullopt;
          palette.push_back(static_cast<char>(p[2]));
          palette.push_back(static_cast<char>(p[1]));
          palette.push_back(static_cast<char>(p[0]));
        }
        last_colour = colour;
        last_index = it->second;
      }
      out[col] = last_index;
    }
  }
  const auto colours = index_of_colour.size();
  const int bit_depth = colours <= 2 ? 1 : colours <= 4 ? 2 : colours <= 16 ? 4 : 8;
  std::array<std::uint8_t, 256> identity{};
  for (int level = 0; level < 256; ++level)
    identity[static_cast<std::size_t>(level)] = static_cast<std::uint8_t>(level);
  std::string png(kPngSignature);
  PutChunk(png, "IHDR", Header(bgr.cols, bgr.rows, bit_depth, 3));
  PutChunk(png, "PLTE", palette);
  PutChunk(png, "IDAT",
           Zlib(NewCompressor().get(), PackedRows(bit_depth, indices, cv::Rect(0, 0, bgr.cols, bgr.rows), identity)));
  PutChunk(png, "IEND", "");
  return png;
}

std::string EncodeAnimatedGreyPng(const std::vector<cv::Mat>& frames, const AnimatedPngTiming& timing) {
  if (frames.empty()) throw InputError("APNG encoding: no frames");
  const cv::Size size = frames.front().size();
  for (const cv::Mat& frame : frames) {
    CheckGrey(frame, "frame");
    if (frame.size() != size) throw InputError("APNG encoding: frames of different sizes");
  }
  // The first frame whole, then the rectangle that changed (one pixel when nothing did), blended over what
  // was there with every unchanged pixel in it transparent: only the changed pixels are stored, and the
  // runs of the transparent index between them cost deflate next to nothing.
  std::vector<cv::Rect> rects{cv::Rect(0, 0, size.width, size.height)};
  for (std::size_t i = 1; i < frames.size(); ++i) {
    const cv::Rect changed = ChangedRect(frames[i - 1], frames[i]);
    rects.push_back(changed.empty() ? cv::Rect(0, 0, 1, 1) : changed);
  }
  // Every level of every frame is in the first frame or in a rectangle that changed.
  std::array<bool, 256> present{};
  for (std::size_t i = 0; i < frames.size(); ++i) {
    for (int row = 0; row < rects[i].height; ++row) {
      const std::uint8_t* pixels = frames[i].ptr<std::uint8_t>(rects[i].y + row) + rects[i].x;
      for (int col = 0; col < rects[i].width; ++col) present[pixels[col]] = true;
    }
  }
  std::array<std::uint8_t, 256> index_of{};
  std::string palette;
  for (int level = 0; level < 256; ++level) {
    if (!present[static_cast<std::size_t>(level)]) continue;
    index_of[static_cast<std::size_t>(level)] = static_cast<std::uint8_t>(palette.size() / 3);
    palette.append(3, static_cast<char>(level));
  }
  auto levels = static_cast<int>(palette.size() / 3);
  // The transparent index after the levels; with all 256 levels in use there is none, and the later frames
  // replace their rectangles whole.
  const bool blend_over = frames.size() > 1 && levels < 256;
  const auto unchanged = static_cast<std::uint8_t>(levels);
  if (blend_over) {
    palette.append(3, '\0');
    ++levels;
  }
  const int bit_depth = levels <= 2 ? 1 : levels <= 4 ? 2 : levels <= 16 ? 4 : 8;

  std::string png(kPngSignature);
  PutChunk(png, "IHDR", Header(size.width, size.height, bit_depth, 3));
  std::string actl;
  PutU32(actl, static_cast<std::uint32_t>(frames.size()));
  PutU32(actl, 0);  // loop forever
  PutChunk(png, "acTL", actl);
  PutChunk(png, "PLTE", palette);
  if (blend_over) {
    // tRNS: every level opaque, the last index fully transparent.
    std::string alpha(static_cast<std::size_t>(levels - 1), '\xff');
    alpha.push_back('\0');
    PutChunk(png, "tRNS", alpha);
  }
  std::uint32_t sequence = 0;
  const Compressor compressor = NewCompressor();
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const int delay = i + 1 == frames.size() ? timing.last_frame_delay_cs : timing.frame_delay_cs;
    const cv::Rect& rect = rects[i];
    const bool over = blend_over && i > 0;
    PutChunk(png, "fcTL", FrameControl(sequence++, rect, delay, over));
    const std::string data = Zlib(
        compressor.get(), PackedRows(bit_depth, frames[i], rect, index_of, over ? &frames[i - 1] : nullptr, unchanged));
    if (i == 0) {
      PutChunk(png, "IDAT", data);
    } else {
      std::string fdat;
      PutU32(fdat, sequence++);
      fdat += data;
      PutChunk(png, "fdAT", fdat);
    }
  }
  PutChunk(png, "IEND", "");
  return png;
}

}  // namespace slamsweep::evaluator::inline formats::inline map
