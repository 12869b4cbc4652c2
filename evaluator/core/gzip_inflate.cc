#include "evaluator/core/gzip_inflate.h"

#include <libdeflate.h>

#include <cstdint>
#include <memory>

namespace slamsweep::evaluator::inline core {

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
  // for several (the buffer doubles when it is too small).
  std::size_t guess = std::size_t{1} << 16;
  if (compressed.size() >= 4) {
    const auto* tail = reinterpret_cast<const unsigned char*>(compressed.data() + compressed.size() - 4);
    const std::uint32_t isize = static_cast<std::uint32_t>(tail[0]) | static_cast<std::uint32_t>(tail[1]) << 8 |
                                static_cast<std::uint32_t>(tail[2]) << 16 | static_cast<std::uint32_t>(tail[3]) << 24;
    guess = std::max<std::size_t>(guess, isize);
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
      if (out.size() > out.max_size() / 2) return std::nullopt;
      out.resize(out.size() * 2);
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
