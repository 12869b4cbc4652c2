#include "evaluator/formats/rosbag2/compression.h"

#include <fmt/format.h>
#include <lz4frame.h>
#include <zstd.h>
#include <zstd_errors.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "evaluator/core/gzip_inflate.h"
#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {
namespace {

/// Reserved up front at most: a stated size is only believed as far as the data bears it out.
constexpr std::uint64_t kMaxReservedBytes = std::uint64_t{256} << 20;

/// What compressed data may inflate to: the rule of gzip input (GzipInflateCap: 100 times the compressed
/// size, at least 16 MiB), so a damaged or hostile chunk costs memory in proportion to its own size.
class InflateLimit {
 public:
  InflateLimit(std::size_t compressed_bytes, std::optional<std::uint64_t> expected_size, const std::string& where,
               const char* format)
      : compressed_bytes_(compressed_bytes),
        cap_(GzipInflateCap(compressed_bytes)),
        expected_size_(expected_size),
        where_(where),
        format_(format) {
    if (expected_size_ && *expected_size_ > cap_) {
      throw InputError(fmt::format("{}: the record states {} bytes of decompressed data; {}", where_, *expected_size_,
                                   InflateCapMessage(format_, "compressed data", compressed_bytes_)));
    }
  }

  std::uint64_t Cap() const { return cap_; }

  /// A size a frame header declares (before anything is allocated for it).
  void CheckDeclared(std::uint64_t declared) const {
    if (declared > cap_) {
      throw InputError(fmt::format("{}: a {} frame header declares {} bytes of content; {}", where_, format_, declared,
                                   InflateCapMessage(format_, "compressed data", compressed_bytes_)));
    }
    if (expected_size_ && declared > *expected_size_) {
      throw InputError(fmt::format("{}: a {} frame header declares {} bytes of content, the record states {}", where_,
                                   format_, declared, *expected_size_));
    }
  }

  void Reserve(std::vector<std::uint8_t>& out) const {
    if (expected_size_) out.reserve(static_cast<std::size_t>(std::min(*expected_size_, kMaxReservedBytes)));
  }

  /// Stops inflating as soon as the output passes what the record states, or the cap.
  void CheckGrowth(std::size_t size) const {
    if (expected_size_ && size > *expected_size_) {
      throw InputError(
          fmt::format("{}: {} data inflates past the {} bytes the record states", where_, format_, *expected_size_));
    }
    if (size > cap_) {
      throw InputError(fmt::format("{}: {}", where_, InflateCapMessage(format_, "compressed data", compressed_bytes_)));
    }
  }

  void CheckSize(std::size_t size) const {
    if (expected_size_ && size != *expected_size_) {
      throw InputError(fmt::format("{}: {} data inflates to {} bytes, the record states {}", where_, format_, size,
                                   *expected_size_));
    }
  }

 private:
  std::size_t compressed_bytes_;
  std::uint64_t cap_;
  std::optional<std::uint64_t> expected_size_;
  const std::string& where_;
  const char* format_;
};

/// The largest zstd window (log2 bytes) a frame may ask for: the cap rounded up to a power of two. libzstd
/// allocates the window a frame header asks for (up to 128 MiB by default) before it decodes a byte.
int ZstdWindowLogMax(std::uint64_t cap) {
  const ZSTD_bounds bounds = ZSTD_dParam_getBounds(ZSTD_d_windowLogMax);
  int log = bounds.lowerBound;
  while (log < bounds.upperBound && (std::uint64_t{1} << log) < cap) ++log;
  return log;
}

[[noreturn]] void ThrowZstdError(std::size_t code, const InflateLimit& limit, const std::string& where) {
  if (ZSTD_getErrorCode(code) == ZSTD_error_frameParameter_windowTooLarge) {
    throw InputError(fmt::format(
        "{}: a zstd frame asks for a window larger than {} bytes, the power of two above the cap of {} bytes for "
        "this compressed data (100 times its size, at least 16 MiB)",
        where, std::uint64_t{1} << ZstdWindowLogMax(limit.Cap()), limit.Cap()));
  }
  throw InputError(fmt::format("{}: damaged zstd data ({})", where, ZSTD_getErrorName(code)));
}

}  // namespace

std::vector<std::uint8_t> ZstdDecompress(std::span<const std::uint8_t> compressed, const std::string& where,
                                         std::optional<std::uint64_t> expected_size) {
  const InflateLimit limit(compressed.size(), expected_size, where, "zstd");
  // The first frame's stated content size is checked before anything is allocated; later frames by their output.
  if (!compressed.empty()) {
    const unsigned long long declared = ZSTD_getFrameContentSize(compressed.data(), compressed.size());
    if (declared != ZSTD_CONTENTSIZE_UNKNOWN && declared != ZSTD_CONTENTSIZE_ERROR) limit.CheckDeclared(declared);
  }
  std::unique_ptr<ZSTD_DStream, decltype(&ZSTD_freeDStream)> stream(ZSTD_createDStream(), &ZSTD_freeDStream);
  if (!stream) throw std::runtime_error("libzstd: cannot create a decompression stream");
  if (ZSTD_isError(ZSTD_DCtx_setParameter(stream.get(), ZSTD_d_windowLogMax, ZstdWindowLogMax(limit.Cap())))) {
    throw std::runtime_error("libzstd: cannot limit the window size");
  }
  std::vector<std::uint8_t> out;
  limit.Reserve(out);
  std::vector<std::uint8_t> buffer(ZSTD_DStreamOutSize());
  ZSTD_inBuffer input{compressed.data(), compressed.size(), 0};
  std::size_t last = 1;  // 0 once a frame is complete
  while (input.pos < input.size) {
    ZSTD_outBuffer output{buffer.data(), buffer.size(), 0};
    last = ZSTD_decompressStream(stream.get(), &output, &input);
    if (ZSTD_isError(last)) ThrowZstdError(last, limit, where);
    out.insert(out.end(), buffer.data(), buffer.data() + output.pos);
    limit.CheckGrowth(out.size());
    // Flush what the decoder still holds once the input is used up; a frame that ends exactly at the end of a full
    // buffer is complete (0): calling again would start the next frame's header.
    while (last != 0 && input.pos == input.size && output.pos == output.size) {
      output = ZSTD_outBuffer{buffer.data(), buffer.size(), 0};
      last = ZSTD_decompressStream(stream.get(), &output, &input);
      if (ZSTD_isError(last)) ThrowZstdError(last, limit, where);
      out.insert(out.end(), buffer.data(), buffer.data() + output.pos);
      limit.CheckGrowth(out.size());
    }
  }
  if (last != 0) throw InputError(fmt::format("{}: truncated zstd data (the last frame is incomplete)", where));
  limit.CheckSize(out.size());
  return out;
}

std::vector<std::uint8_t> Lz4FrameDecompress(std::span<const std::uint8_t> compressed, const std::string& where,
                                             std::optional<std::uint64_t> expected_size) {
  LZ4F_dctx* context = nullptr;
  if (LZ4F_isError(LZ4F_createDecompressionContext(&context, LZ4F_VERSION))) {
    throw std::runtime_error("liblz4: cannot create a decompression context");
  }
  std::unique_ptr<LZ4F_dctx, decltype(&LZ4F_freeDecompressionContext)> owner(context, &LZ4F_freeDecompressionContext);
  const InflateLimit limit(compressed.size(), expected_size, where, "lz4");
  if (compressed.empty()) throw InputError(fmt::format("{}: truncated lz4 data (no frame header)", where));
  // The first frame's header, with its content size when it states one, is read before anything is allocated.
  LZ4F_frameInfo_t info{};
  std::size_t position = compressed.size();
  std::size_t hint = LZ4F_getFrameInfo(context, &info, compressed.data(), &position);
  if (LZ4F_isError(hint)) {
    throw InputError(fmt::format("{}: damaged lz4 data ({})", where, LZ4F_getErrorName(hint)));
  }
  if (info.contentSize != 0) limit.CheckDeclared(info.contentSize);
  std::vector<std::uint8_t> out;
  limit.Reserve(out);
  std::vector<std::uint8_t> buffer(std::size_t{1} << 16);
  while (position < compressed.size()) {
    std::size_t produced = buffer.size();
    std::size_t consumed = compressed.size() - position;
    hint = LZ4F_decompress(context, buffer.data(), &produced, compressed.data() + position, &consumed, nullptr);
    if (LZ4F_isError(hint)) {
      throw InputError(fmt::format("{}: damaged lz4 data ({})", where, LZ4F_getErrorName(hint)));
    }
    if (produced == 0 && consumed == 0) break;
    position += consumed;
    out.insert(out.end(), buffer.data(), buffer.data() + produced);
    limit.CheckGrowth(out.size());
  }
  // Output the decoder still holds.
  for (std::size_t produced = buffer.size(); hint != 0 && produced > 0;) {
    produced = buffer.size();
    std::size_t consumed = 0;
    hint = LZ4F_decompress(context, buffer.data(), &produced, nullptr, &consumed, nullptr);
    if (LZ4F_isError(hint)) {
      throw InputError(fmt::format("{}: damaged lz4 data ({})", where, LZ4F_getErrorName(hint)));
    }
    out.insert(out.end(), buffer.data(), buffer.data() + produced);
    limit.CheckGrowth(out.size());
  }
  if (hint != 0) throw InputError(fmt::format("{}: truncated lz4 data (the last frame is incomplete)", where));
  limit.CheckSize(out.size());
  return out;
}

std::vector<std::uint8_t> ZstdCompress(std::span<const std::uint8_t> bytes) {
  std::vector<std::uint8_t> out(ZSTD_compressBound(bytes.size()));
  const std::size_t size = ZSTD_compress(out.data(), out.size(), bytes.data(), bytes.size(), ZSTD_CLEVEL_DEFAULT);
  if (ZSTD_isError(size)) throw std::runtime_error(std::string("libzstd: ") + ZSTD_getErrorName(size));
  out.resize(size);
  return out;
}

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
