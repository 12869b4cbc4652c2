#include "evaluator/formats/map/png_image.h"

#include <fmt/format.h>
#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <csetjmp>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/png_signature.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace slamsweep::evaluator::inline formats::inline map {
namespace {

/// libpng reports errors through a callback that must not return: it records the reason here and
/// jumps back to the setjmp of the call in progress (libpng's documented error protocol).
struct PngErrors {
  std::string message;
};

void OnPngError(png_structp png, png_const_charp message) {
  static_cast<PngErrors*>(png_get_error_ptr(png))->message = message;
  png_longjmp(png, 1);
}

void OnPngWarning(png_structp, png_const_charp) {}

struct ReadCursor {
  std::string_view bytes;
  std::size_t position = 0;
};

void ReadFromBytes(png_structp png, png_bytep out, png_size_t count) {
  auto* cursor = static_cast<ReadCursor*>(png_get_io_ptr(png));
  if (count > cursor->bytes.size() - cursor->position) png_error(png, "PNG data ends early (truncated file?)");
  std::memcpy(out, cursor->bytes.data() + cursor->position, count);
  cursor->position += count;
}

void AppendToString(png_structp png, png_bytep data, png_size_t count) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), count);
}

void FlushNothing(png_structp) {}

/// Runs libpng calls with libpng's error protocol: an error jumps back here and makes this return
/// false. `step` must not own objects with destructors (a jump would skip them); the caller owns them.
template <typename Step>
bool RunPngStep(png_structp png, Step&& step) {
  if (setjmp(png_jmpbuf(png)) != 0) return false;
  step();
  return true;
}

/// The channel count OpenCV's PNG decoder chooses for a colour type, and so the layout map_server
/// rules are written for.
int ChannelsFor(png_structp png, png_infop info, int color_type) {
  switch (color_type) {
    case PNG_COLOR_TYPE_RGB:
    case PNG_COLOR_TYPE_PALETTE: {
      png_bytep trans = nullptr;
      int num_trans = 0;
      png_color_16p trans_values = nullptr;
      png_get_tRNS(png, info, &trans, &num_trans, &trans_values);
      return num_trans > 0 ? 4 : 3;
    }
    case PNG_COLOR_TYPE_GRAY_ALPHA:
    case PNG_COLOR_TYPE_RGB_ALPHA:
      return 4;
    default:
      return 1;
  }
}

/// Which grey levels `grey` holds. Maps are long runs of one level: sixteen pixels equal to the
/// last level seen are passed over at once.
std::array<bool, 256> GreyLevelsPresent(const cv::Mat& grey) {
  std::array<bool, 256> present{};
  for (int row = 0; row < grey.rows; ++row) {
    const std::uint8_t* pixels = grey.ptr<std::uint8_t>(row);
    std::uint8_t last = pixels[0];
    present[last] = true;
    int col = 0;
#if defined(__SSE2__)
    for (; col + 16 <= grey.cols; col += 16) {
      const __m128i sixteen = _mm_loadu_si128(reinterpret_cast<const __m128i*>(pixels + col));
      if (_mm_movemask_epi8(_mm_cmpeq_epi8(sixteen, _mm_set1_epi8(static_cast<char>(last)))) == 0xFFFF) continue;
      for (int k = 0; k < 16; ++k) present[pixels[col + k]] = true;
      last = pixels[col + 15];
    }
#endif
    for (; col < grey.cols; ++col) present[pixels[col]] = true;
  }
  return present;
}

#if defined(__SSE2__)
/// PackRow<2> for up to four levels, sixty-four pixels per step: each pixel's index from three
/// byte compares, then four indices per byte by shifts within each 32-bit lane.
int PackTwoBitRowQuick(const std::uint8_t* pixels, int width, const std::vector<png_color>& palette, png_byte* out) {
  // A palette of fewer than four levels compares the missing ones with a grey it does not hold.
  int absent = 0;
  while (std::any_of(palette.begin(), palette.end(), [&](const png_color& c) { return c.red == absent; })) ++absent;
  const auto level = [&](std::size_t k) {
    return _mm_set1_epi8(static_cast<char>(k < palette.size() ? palette[k].red : absent));
  };
  const __m128i level1 = level(1);
  const __m128i level2 = level(2);
  const __m128i level3 = level(3);
  const __m128i two_bits = _mm_set1_epi32(0x03);
  int col = 0;
  for (; col + 64 <= width; col += 64) {
    __m128i lanes[4];
    for (int k = 0; k < 4; ++k) {
      const __m128i p = _mm_loadu_si128(reinterpret_cast<const __m128i*>(pixels + col + 16 * k));
      // The levels differ, so at most one compare holds: index 1, 2 or 3 (0 when none does).
      const __m128i index = _mm_or_si128(_mm_or_si128(_mm_and_si128(_mm_cmpeq_epi8(p, level1), _mm_set1_epi8(1)),
                                                      _mm_and_si128(_mm_cmpeq_epi8(p, level2), _mm_set1_epi8(2))),
                                         _mm_and_si128(_mm_cmpeq_epi8(p, level3), _mm_set1_epi8(3)));
      // Lane bytes b0 b1 b2 b3 (b0 lowest) -> b0 << 6 | b1 << 4 | b2 << 2 | b3.
      lanes[k] = _mm_or_si128(_mm_or_si128(_mm_slli_epi32(_mm_and_si128(index, two_bits), 6),
                                           _mm_slli_epi32(_mm_and_si128(_mm_srli_epi32(index, 8), two_bits), 4)),
                              _mm_or_si128(_mm_slli_epi32(_mm_and_si128(_mm_srli_epi32(index, 16), two_bits), 2),
                                           _mm_and_si128(_mm_srli_epi32(index, 24), two_bits)));
    }
    const __m128i bytes = _mm_packus_epi16(_mm_packs_epi32(lanes[0], lanes[1]), _mm_packs_epi32(lanes[2], lanes[3]));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + col / 4), bytes);
  }
  return col;
}
#endif

/// One row of palette indices packed kBits to a pixel, the first pixel in the highest bits.
template <int kBits>
void PackRow(const std::uint8_t* pixels, int width, const std::array<std::uint8_t, 256>& index_of, png_byte* out) {
  constexpr int kPerByte = 8 / kBits;
  int col = 0;
  for (; col + kPerByte <= width; col += kPerByte) {
    unsigned byte = 0;
    for (int k = 0; k < kPerByte; ++k) byte = (byte << kBits) | index_of[pixels[col + k]];
    *out++ = static_cast<png_byte>(byte);
  }
  if (col == width) return;
  unsigned byte = 0;
  int k = 0;
  for (; col < width; ++col, ++k) byte = (byte << kBits) | index_of[pixels[col]];
  *out = static_cast<png_byte>(byte << (kBits * (kPerByte - k)));
}

}  // namespace

bool LooksLikePng(std::string_view bytes) { return bytes.starts_with(kPngSignature); }

cv::Mat DecodePng(std::string_view bytes, const std::filesystem::path& source) {
  PngErrors errors;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &errors, OnPngError, OnPngWarning);
  if (png == nullptr) throw InputError(Located(source, 0, "PNG decoder could not start (out of memory?)"));
  png_infop info = png_create_info_struct(png);
  ReadCursor cursor{bytes, 0};
  png_uint_32 width = 0;
  png_uint_32 height = 0;
  int bit_depth = 0;
  int color_type = 0;
  int channels = 1;
  cv::Mat image;
  std::vector<png_bytep> rows;
  const auto fail = [&](const std::string& message) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw InputError(Located(source, 0, message));
  };
  const auto corrupt = [&] {
    fail("not a readable image, or a truncated/corrupt one (expected a PGM or PNG map): " +
         (errors.message.empty() ? std::string("the PNG decoder failed") : errors.message));
  };
  if (info == nullptr) fail("PNG decoder could not start (out of memory?)");
  const bool header_read = RunPngStep(png, [&] {
    png_set_read_fn(png, &cursor, ReadFromBytes);
    png_read_info(png, info);
    png_get_IHDR(png, info, &width, &height, &bit_depth, &color_type, nullptr, nullptr, nullptr);
  });
  if (!header_read) corrupt();
  if (bit_depth == 16) fail("16-bit samples; expected an 8-bit image, as map_server reads");
  // The pixels are deflate data, which inflates at most 1032 times: a header that claims more rows of pixels
  // than the whole file could inflate to is refused before anything is allocated for them.
  const std::uint64_t pixel_bytes = std::uint64_t{height} * (std::uint64_t{png_get_rowbytes(png, info)} + 1);
  if (pixel_bytes > 1032 * std::uint64_t{bytes.size()}) {
    fail(
        fmt::format("the header claims {} x {} pixels ({} bytes of pixel data), more than the file's {} bytes "
                    "can hold compressed",
                    width, height, pixel_bytes, bytes.size()));
  }
  channels = ChannelsFor(png, info, color_type);
  const bool pixels_read = RunPngStep(png, [&] {
    // The transformations OpenCV's decoder applies, with R, G, B kept in file order (no BGR swap).
    if (channels < 4) {
      png_set_strip_alpha(png);
    } else {
      png_set_tRNS_to_alpha(png);
    }
    if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if ((color_type & PNG_COLOR_MASK_COLOR) == 0 && bit_depth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if ((color_type & PNG_COLOR_MASK_COLOR) == 0 && channels > 1) png_set_gray_to_rgb(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    image.create(static_cast<int>(height), static_cast<int>(width), CV_8UC(channels));
    if (png_get_rowbytes(png, info) != image.step[0]) png_error(png, "unexpected row size after transformations");
    rows.resize(height);
    for (png_uint_32 row = 0; row < height; ++row) rows[row] = image.ptr<png_byte>(static_cast<int>(row));
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
  });
  if (!pixels_read) corrupt();
  png_destroy_read_struct(&png, &info, nullptr);
  return image;
}

std::string EncodePngBytes(const cv::Mat& image) {
  const int channels = image.channels();
  if (image.depth() != CV_8U || (channels != 1 && channels != 3 && channels != 4) || image.empty()) {
    throw InputError("PNG encoding: expected a non-empty 8-bit image with 1, 3 or 4 channels");
  }
  PngErrors errors;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, OnPngError, OnPngWarning);
  if (png == nullptr) throw InputError("PNG encoding failed (out of memory?)");
  png_infop info = png_create_info_struct(png);
  std::string out;
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.rows));
  for (int row = 0; row < image.rows; ++row) {
    rows[static_cast<std::size_t>(row)] = const_cast<png_bytep>(image.ptr<png_byte>(row));
  }
  const bool written =
      info != nullptr && RunPngStep(png, [&] {
        png_set_write_fn(png, &out, AppendToString, FlushNothing);
        // OpenCV's choices when no compression level is given ("tuned for speed").
        png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
        png_set_compression_level(png, Z_BEST_SPEED);
        png_set_compression_strategy(png, Z_RLE);
        png_set_IHDR(png, info, static_cast<png_uint_32>(image.cols), static_cast<png_uint_32>(image.rows), 8,
                     channels == 1   ? PNG_COLOR_TYPE_GRAY
                     : channels == 3 ? PNG_COLOR_TYPE_RGB
                                     : PNG_COLOR_TYPE_RGB_ALPHA,
                     PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_write_info(png, info);
        png_set_bgr(png);
        png_write_image(png, rows.data());
        png_write_end(png, info);
      });
  png_destroy_write_struct(&png, &info);
  if (!written) throw InputError("PNG encoding failed: " + errors.message);
  return out;
}

std::string EncodeGreyPalettePng(const cv::Mat& grey) {
  if (grey.type() != CV_8UC1 || grey.empty()) {
    throw InputError("PNG encoding: expected a non-empty 8-bit single-channel image for a grey palette");
  }
  const std::array<bool, 256> present = GreyLevelsPresent(grey);
  std::array<std::uint8_t, 256> index_of{};
  std::vector<png_color> palette;
  for (int level = 0; level < 256; ++level) {
    if (!present[static_cast<std::size_t>(level)]) continue;
    index_of[static_cast<std::size_t>(level)] = static_cast<std::uint8_t>(palette.size());
    const auto value = static_cast<png_byte>(level);
    palette.push_back(png_color{value, value, value});
  }
  const int bit_depth = palette.size() <= 2 ? 1 : palette.size() <= 4 ? 2 : palette.size() <= 16 ? 4 : 8;
  const std::size_t row_bytes = (static_cast<std::size_t>(grey.cols) * static_cast<std::size_t>(bit_depth) + 7) / 8;
  std::vector<png_byte> packed(row_bytes * static_cast<std::size_t>(grey.rows));
  std::vector<png_bytep> rows(static_cast<std::size_t>(grey.rows));
  for (int row = 0; row < grey.rows; ++row) {
    png_byte* out = packed.data() + static_cast<std::size_t>(row) * row_bytes;
    rows[static_cast<std::size_t>(row)] = out;
    const std::uint8_t* pixels = grey.ptr<std::uint8_t>(row);
    switch (bit_depth) {
      case 1:
        PackRow<1>(pixels, grey.cols, index_of, out);
        break;
      case 2: {
        int done = 0;
#if defined(__SSE2__)
        done = PackTwoBitRowQuick(pixels, grey.cols, palette, out);
#endif
        PackRow<2>(pixels + done, grey.cols - done, index_of, out + done / 4);
        break;
      }
      case 4:
        PackRow<4>(pixels, grey.cols, index_of, out);
        break;
      default:
        PackRow<8>(pixels, grey.cols, index_of, out);
    }
  }
  PngErrors errors;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, OnPngError, OnPngWarning);
  if (png == nullptr) throw InputError("PNG encoding failed (out of memory?)");
  png_infop info = png_create_info_struct(png);
  std::string encoded;
  const bool written =
      info != nullptr && RunPngStep(png, [&] {
        png_set_write_fn(png, &encoded, AppendToString, FlushNothing);
        png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
        png_set_compression_level(png, Z_BEST_SPEED);
        png_set_compression_strategy(png, Z_RLE);
        png_set_IHDR(png, info, static_cast<png_uint_32>(grey.cols), static_cast<png_uint_32>(grey.rows), bit_depth,
                     PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
        png_set_check_for_invalid_index(png, 0);  // every index is below the palette size by construction
        png_write_info(png, info);
        png_write_image(png, rows.data());
        png_write_end(png, info);
      });
  png_destroy_write_struct(&png, &info);
  if (!written) throw InputError("PNG encoding failed: " + errors.message);
  return encoded;
}

}  // namespace slamsweep::evaluator::inline formats::inline map
