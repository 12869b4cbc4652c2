#include "evaluator/formats/rosbag2/compression.h"

#include <fmt/format.h>
#include <lz4frame.h>
#include <zstd.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {
namespace {

/// Decompressed data beyond this is refused: a corrupt size must not exhaust memory.
constexpr std::uint64_t kMaxDecompressedBytes = std::uint64_t{16} << 30;
/// Reserved up front at most: a stated size is only believed as far as the data bears it out.
constexpr std::uint64_t kMaxReservedBytes = std::uint64_t{256} << 20;

void CheckSize(std::size_t size, std::optional<std::uint64_t> expected_size, const std::string& where,
               const char* format) {
  if (expected_size && size != *expected_size) {
    throw InputError(
        fmt::format("{}: {} data inflates to {} bytes, the record states {}", where, format, size, *expected_size));
  }
}

void Reserve(std::vector<std::uint8_t>& out, std::optional<std::uint64_t> expected_size, const std::string& where) {
  if (!expected_size) return;
  if (*expected_size > kMaxDecompressedBytes) {
    throw InputError(fmt::format("{}: states {} bytes of decompressed data, more than the {} GiB slamsweep accepts",
                                 where, *expected_size, kMaxDecompressedBytes >> 30));
  }
  out.reserve(static_cast<std::size_t>(std::min(*expected_size, kMaxReservedBytes)));
}

/// Stops inflating as soon as the output passes what the record states, or the overall limit.
void CheckGrowth(std::size_t size, std::optional<std::uint64_t> expected_size, const std::string& where,
                 const char* format) {
  if (expected_size && size > *expected_size) {
    throw InputError(
        fmt::format("{}: {} data inflates past the {} bytes the record states", where, format, *expected_size));
  }
  if (size > kMaxDecompressedBytes) {
    throw InputError(fmt::format("{}: {} data inflates past {} GiB", where, format, kMaxDecompressedBytes >> 30));
  }
}

}  // namespace

std::vector<std::uint8_t> ZstdDecompress(std::span<const std::uint8_t> compressed, const std::string& where,
                                         std::optional<std::uint64_t> expected_size) {
  std::unique_ptr<ZSTD_DStream, decltype(&ZSTD_freeDStream)> stream(ZSTD_createDStream(), &ZSTD_freeDStream);
  if (!stream) throw std::runtime_error("libzstd: cannot create a decompression stream");
  std::vector<std::uint8_t> out;
  Reserve(out, expected_size, where);
  std::vector<std::uint8_t> buffer(ZSTD_DStreamOutSize());
  ZSTD_inBuffer input{compressed.data(), compressed.size(), 0};
  std::size_t last = 1;  // 0 once a frame is complete
  while (input.pos < input.size) {
    ZSTD_outBuffer output{buffer.data(), buffer.size(), 0};
    last = ZSTD_decompressStream(stream.get(), &output, &input);
    if (ZSTD_isError(last)) {
      throw InputError(fmt::format("{}: damaged zstd data ({})", where, ZSTD_getErrorName(last)));
    }
    out.insert(out.end(), buffer.data(), buffer.data() + output.pos);
    CheckGrowth(out.size(), expected_size, where, "zstd");
    // Flush what the decoder still holds once the input is used up.
    while (input.pos == input.size && output.pos == output.size) {
      output = ZSTD_outBuffer{buffer.data(), buffer.size(), 0};
      last = ZSTD_decompressStream(stream.get(), &output, &input);
      if (ZSTD_isError(last)) {
        throw InputError(fmt::format("{}: damaged zstd data ({})", where, ZSTD_getErrorName(last)));
      }
      out.insert(out.end(), buffer.data(), buffer.data() + output.pos);
      CheckGrowth(out.size(), expected_size, where, "zstd");
    }
  }
  if (last != 0) throw InputError(fmt::format("{}: truncated zstd data (the last frame is incomplete)", where));
  CheckSize(out.size(), expected_size, where, "zstd");
  return out;
}

std::vector<std::uint8_t> Lz4FrameDecompress(std::span<const std::uint8_t> compressed, const std::string& where,
                                             std::optional<std::uint64_t> expected_size) {
  LZ4F_dctx* context = nullptr;
  if (LZ4F_isError(LZ4F_createDecompressionContext(&context, LZ4F_VERSION))) {
    throw std::runtime_error("liblz4: cannot create a decompression context");
  }
  std::unique_ptr<LZ4F_dctx, decltype(&LZ4F_freeDecompressionContext)> owner(context, &LZ4F_freeDecompressionContext);
  std::vector<std::uint8_t> out;
  Reserve(out, expected_size, where);
  std::vector<std::uint8_t> buffer(std::size_t{1} << 16);
  std::size_t position = 0;
  std::size_t hint = 1;  // 0 once a frame is complete
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
    CheckGrowth(out.size(), expected_size, where, "lz4");
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
    CheckGrowth(out.size(), expected_size, where, "lz4");
  }
  if (hint != 0) throw InputError(fmt::format("{}: truncated lz4 data (the last frame is incomplete)", where));
  CheckSize(out.size(), expected_size, where, "lz4");
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
