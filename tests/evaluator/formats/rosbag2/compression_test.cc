// The zstd and lz4 decompressors of ROS 2 bags on hostile input: output is capped by the size of the
// compressed data (as gzip input is: 100 times, at least 16 MiB), a size a record or a frame header states
// beyond the cap is refused before anything is allocated, and every error names where the data came from.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <lz4frame.h>
#include <zstd.h>

#include <cstdint>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/rosbag2/compression.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

constexpr char kWhere[] = "bag.mcap: Chunk record at byte 8";
constexpr std::size_t kMiB = std::size_t{1} << 20;

/// A zstd frame whose header does not state its content size (as a streaming writer makes it).
std::vector<std::uint8_t> ZstdStreamed(const std::vector<std::uint8_t>& bytes) {
  std::vector<std::uint8_t> out(ZSTD_compressBound(bytes.size()));
  ZSTD_CCtx* context = ZSTD_createCCtx();
  ZSTD_CCtx_setParameter(context, ZSTD_c_contentSizeFlag, 0);
  const std::size_t size = ZSTD_compress2(context, out.data(), out.size(), bytes.data(), bytes.size());
  ZSTD_freeCCtx(context);
  EXPECT_FALSE(ZSTD_isError(size));
  out.resize(size);
  EXPECT_EQ(ZSTD_getFrameContentSize(out.data(), out.size()), ZSTD_CONTENTSIZE_UNKNOWN);
  return out;
}

/// An lz4 frame of `bytes`, its content size in the header when `state_size`.
std::vector<std::uint8_t> Lz4Frame(const std::vector<std::uint8_t>& bytes, bool state_size) {
  LZ4F_preferences_t preferences{};
  preferences.frameInfo.contentSize = state_size ? bytes.size() : 0;
  std::vector<std::uint8_t> out(LZ4F_compressFrameBound(bytes.size(), &preferences));
  const std::size_t size = LZ4F_compressFrame(out.data(), out.size(), bytes.data(), bytes.size(), &preferences);
  EXPECT_FALSE(LZ4F_isError(size));
  out.resize(size);
  return out;
}

TEST(Rosbag2CompressionTest, DataUnderTheCapInflates) {
  // 1 MiB: a whole number of libzstd's output buffers (128 KiB), which once read as a cut frame.
  const std::vector<std::uint8_t> bytes(kMiB, 7);
  EXPECT_EQ(ZstdDecompress(ZstdCompress(bytes), kWhere, bytes.size()), bytes);
  EXPECT_EQ(ZstdDecompress(ZstdStreamed(bytes), kWhere), bytes);
  EXPECT_EQ(Lz4FrameDecompress(Lz4Frame(bytes, true), kWhere, bytes.size()), bytes);
  EXPECT_EQ(Lz4FrameDecompress(Lz4Frame(bytes, false), kWhere), bytes);
}

TEST(Rosbag2CompressionTest, AZstdFrameStatingMoreThanTheCapIsRefusedBeforeInflating) {
  // 40 MiB of zeros are about a kilobyte of zstd: its cap is 16 MiB.
  const std::vector<std::uint8_t> compressed = ZstdCompress(std::vector<std::uint8_t>(40 * kMiB, 0));
  ASSERT_LT(compressed.size(), 160u << 10);
  EXPECT_THAT([&] { ZstdDecompress(compressed, kWhere); },
              ThrowsMessage<InputError>(AllOf(HasSubstr(kWhere), HasSubstr("declares 41943040 bytes"),
                                              HasSubstr("more than 16.0 MiB, the cap for compressed data of"))));
}

TEST(Rosbag2CompressionTest, AZstdFrameWithoutItsSizeStopsAtTheCap) {
  const std::vector<std::uint8_t> compressed = ZstdStreamed(std::vector<std::uint8_t>(40 * kMiB, 0));
  EXPECT_THAT([&] { ZstdDecompress(compressed, kWhere); },
              ThrowsMessage<InputError>(AllOf(HasSubstr(kWhere), HasSubstr("zstd data inflates to more than 16.0 MiB"),
                                              HasSubstr("100 times its size, at least 16.0 MiB"))));
}

TEST(Rosbag2CompressionTest, ARecordStatingMoreThanTheCapIsRefusedBeforeInflating) {
  const std::vector<std::uint8_t> compressed = ZstdCompress(std::vector<std::uint8_t>(100, 1));
  const std::uint64_t stated = std::uint64_t{1} << 40;
  for (const auto& decompress : {ZstdDecompress, Lz4FrameDecompress}) {
    EXPECT_THAT([&] { decompress(compressed, kWhere, stated); },
                ThrowsMessage<InputError>(AllOf(HasSubstr(kWhere), HasSubstr("states 1099511627776 bytes"),
                                                HasSubstr("the cap for compressed data of"))));
  }
}

TEST(Rosbag2CompressionTest, AZstdFrameAskingForAWindowBeyondTheCapIsRefused) {
  // Magic, a frame header with no content size and a 128 MiB window (2^(10 + 17)), one empty last raw block:
  // libzstd would allocate the window before decoding the block.
  const std::vector<std::uint8_t> frame = {0x28, 0xb5, 0x2f, 0xfd, 0x00, 17 << 3, 0x01, 0x00, 0x00};
  EXPECT_THAT([&] { ZstdDecompress(frame, kWhere); },
              ThrowsMessage<InputError>(AllOf(HasSubstr(kWhere), HasSubstr("asks for a window larger than 16777216"))));
}

TEST(Rosbag2CompressionTest, AnLz4FrameBeyondTheCapIsRefused) {
  const std::vector<std::uint8_t> zeros(20 * kMiB, 0);
  const std::vector<std::uint8_t> stated = Lz4Frame(zeros, true);
  ASSERT_LT(stated.size(), 16 * kMiB / 100);
  EXPECT_THAT([&] { Lz4FrameDecompress(stated, kWhere); },
              ThrowsMessage<InputError>(AllOf(HasSubstr(kWhere), HasSubstr("lz4 frame header declares 20971520"))));
  EXPECT_THAT(
      [&] { Lz4FrameDecompress(Lz4Frame(zeros, false), kWhere); },
      ThrowsMessage<InputError>(AllOf(HasSubstr(kWhere), HasSubstr("lz4 data inflates to more than 16.0 MiB"))));
}

TEST(Rosbag2CompressionTest, TheCapGrowsWithTheCompressedData) {
  // Bytes that compress about 4:1 (a byte pattern with noise), 32 MiB of them: more than the least cap (16 MiB),
  // far less than 100 times their compressed size.
  std::vector<std::uint8_t> bytes(32 * kMiB);
  std::uint32_t state = 1;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    state = state * 1664525u + 1013904223u;
    bytes[i] = static_cast<std::uint8_t>((i % 64) ^ ((state >> 28) & 3));
  }
  const std::vector<std::uint8_t> compressed = ZstdCompress(bytes);
  ASSERT_GT(compressed.size(), 32 * kMiB / 100);
  EXPECT_EQ(ZstdDecompress(compressed, kWhere, bytes.size()).size(), bytes.size());
}

TEST(Rosbag2CompressionTest, EmptyOrCutDataIsAnErrorNamingWhere) {
  const std::vector<std::uint8_t> empty;
  EXPECT_THAT([&] { ZstdDecompress(empty, kWhere); }, ThrowsMessage<InputError>(HasSubstr(kWhere)));
  EXPECT_THAT([&] { Lz4FrameDecompress(empty, kWhere); }, ThrowsMessage<InputError>(HasSubstr(kWhere)));
  std::vector<std::uint8_t> cut = Lz4Frame(std::vector<std::uint8_t>(1000, 3), true);
  cut.resize(5);
  EXPECT_THAT([&] { Lz4FrameDecompress(cut, kWhere); }, ThrowsMessage<InputError>(HasSubstr(kWhere)));
}

}  // namespace
}  // namespace slamsweep::evaluator
