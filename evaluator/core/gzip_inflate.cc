#include "evaluator/core/gzip_inflate.h"

#include <libdeflate.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <memory>

namespace slamsweep::evaluator::inline core {

namespace {

constexpr std::size_t kMinimumCap = std::size_t{16} << 20;
constexpr std::size_t kCapRatio = 100;

std::string Size(std::size_t bytes) {
  if (bytes < 1024) return fmt::format("{} B", bytes);
  if (bytes < (std::size_t{1} << 20)) return fmt::format("{:.1f} KiB", static_cast<double>(bytes) / 1024.0);
  return fmt::format("{:.1f} MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
}

}  // namespace

std::size_t GzipInflateCap(std::size_t compressed_bytes) {
  const std::size_t ratio_cap = compressed_bytes > SIZE_MAX / kCapRatio ? SIZE_MAX : compressed_bytes * kCapRatio;
  return std::max(kMinimumCap, ratio_cap);
}

std::string GzipInflateCapMessage(std::size_t compressed_bytes) {
  return InflateCapMessage("gzip", "a file", compressed_bytes);
}

std::string InflateCapMessage(std::string_view format, std::string_view what, std::size_t compressed_bytes) {
  return fmt::format("{} data inflates to more than {}, the cap for {} of {} ({} times its size, at least {})", format,
                     Size(GzipInflateCap(compressed_bytes)), what, Size(compressed_bytes), kCapRatio,
                     Size(kMinimumCap));
}

bool HasGzipMagic(std::string_view bytes) {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
         static_cast<unsigned char>(bytes[1]) == 0x8b;
}

std::optional<std::string> InflateWholeGzip(std::string_view compressed) {
  struct Free {
    void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
  };
  const std::unique_ptr<libdeflate_decompressor, Free> decompressor(libdeflate_alloc_decompressor());
  if (!decompressor || !HasGzipMagic(compressed)) return std::nullopt;

  // A member ends with ISIZE, its length mod 2^32: exact for the usual single member, a start
  // for several (the buffer doubles when it is too small). ISIZE is only a claim: never beyond the cap.
  const std::size_t cap = GzipInflateCap(compressed.size());
  std::size_t guess = std::size_t{1} << 16;
  if (compressed.size() >= 4) {
    const auto* tail = reinterpret_cast<const unsigned char*>(compressed.data() + compressed.size() - 4);
    const std::uint32_t isize = static_cast<std::uint32_t>(tail[0]) | static_cast<std::uint32_t>(tail[1]) << 8 |
                                static_cast<std::uint32_t>(tail[2]) << 16 | static_cast<std::uint32_t>(tail[3]) << 24;
    guess = std::min(std::max<std::size_t>(guess, isize), cap);
  }
  std::string out(guess, '\0');
  std::size_t in_pos = 0;
  std::size_t out_pos = 0;
  while (true) {
    std::size_t in_used = 0;
    std::size_t out_used = 0;
    const libdeflate_result result =
        libdeflate_gzip_decompress_ex(decompressor.get(), compressed.data() + in_pos, compressed.size() - in_pos,
                                      out.data() + out_pos, out.size() - out_pos, &in_used, &out_used);
    if (result == LIBDEFLATE_INSUFFICIENT_SPACE) {
      if (out.size() >= cap) return std::nullopt;
      out.resize(std::min(out.size() * 2, cap));
      continue;
    }
    if (result != LIBDEFLATE_SUCCESS) return std::nullopt;
    in_pos += in_used;
    out_pos += out_used;
    if (!HasGzipMagic(compressed.substr(in_pos))) break;
  }
  out.resize(out_pos);
  return out;
}

}  // namespace slamsweep::evaluator::inline core
