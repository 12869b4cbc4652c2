// The zstd and lz4 decompressors of ROS 2 bags (MCAP chunks, rosbag2's per-file and per-message zstd). The
// first byte picks the decompressor (bit 0: lz4) and whether a record states the inflated size (bit 1: the
// next 4 bytes, little endian); the rest is the compressed data. Output must stay within the cap.
#include <lz4frame.h>
#include <zstd.h>

#include <algorithm>

#include "evaluator/core/gzip_inflate.h"
#include "evaluator/formats/rosbag2/compression.h"
#include "evaluator/formats/rosbag2/mapped_file.h"
#include "evaluator/formats/rosbag2/mcap_records.h"
#include "evaluator/formats/rosbag2/rosbag2_writer.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/rosbag2_seeds.h"
#include "tests/fuzz/seed_data.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

namespace {

constexpr char kWhere[] = "input.mcap: Chunk record at byte 8";
constexpr std::uint8_t kLz4 = 1;
constexpr std::uint8_t kStated = 2;

std::string Input(std::uint8_t mode, std::optional<std::uint32_t> stated, std::span<const std::uint8_t> compressed) {
  std::string input(1, static_cast<char>(mode | (stated ? kStated : 0)));
  for (int i = 0; stated && i < 4; ++i) input += static_cast<char>((*stated >> (8 * i)) & 0xff);
  input.append(reinterpret_cast<const char*>(compressed.data()), compressed.size());
  return input;
}

std::vector<std::uint8_t> Lz4(std::span<const std::uint8_t> bytes, bool state_size) {
  LZ4F_preferences_t preferences{};
  preferences.frameInfo.contentSize = state_size ? bytes.size() : 0;
  std::vector<std::uint8_t> out(LZ4F_compressFrameBound(bytes.size(), &preferences));
  out.resize(LZ4F_compressFrame(out.data(), out.size(), bytes.data(), bytes.size(), &preferences));
  return out;
}

std::vector<std::uint8_t> ZstdWithoutSize(std::span<const std::uint8_t> bytes) {
  std::vector<std::uint8_t> out(ZSTD_compressBound(bytes.size()));
  ZSTD_CCtx* context = ZSTD_createCCtx();
  ZSTD_CCtx_setParameter(context, ZSTD_c_contentSizeFlag, 0);
  out.resize(ZSTD_compress2(context, out.data(), out.size(), bytes.data(), bytes.size()));
  ZSTD_freeCCtx(context);
  return out;
}

}  // namespace

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  // The simulated run's MCAP file, compressed in every way the readers meet.
  const fuzz::SeedBag bag = fuzz::WriteSeedBag(fuzz::ScratchPath("seed-bag"), ev::Rosbag2StorageKind::kMcap, 3, false);
  const std::string file = fuzz::FileBytes(bag.split_file);
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(file.data()), file.size());
  const auto size = static_cast<std::uint32_t>(bytes.size());
  seeds.Add("zstd-stated.bin", Input(0, size, ev::ZstdCompress(bytes)));
  seeds.Add("zstd.bin", Input(0, std::nullopt, ev::ZstdCompress(bytes)));
  seeds.Add("zstd-streamed.bin", Input(0, std::nullopt, ZstdWithoutSize(bytes)));
  std::vector<std::uint8_t> two_frames = ev::ZstdCompress(bytes.first(size / 2));
  const std::vector<std::uint8_t> second = ev::ZstdCompress(bytes.subspan(size / 2));
  two_frames.insert(two_frames.end(), second.begin(), second.end());
  seeds.Add("zstd-two-frames.bin", Input(0, size, two_frames));
  seeds.Add("lz4-stated.bin", Input(kLz4, size, Lz4(bytes, true)));
  seeds.Add("lz4.bin", Input(kLz4, std::nullopt, Lz4(bytes, false)));
  // The real MCAP file has one zstd chunk of 362 KB (2.9 MB inflated), too big a seed: the first 16 KiB of its
  // records, inflated by slamsweep's reader, compressed again both ways.
  if (const auto shared = fuzz::SharedPath(seeds, fuzz::kSharedMcap)) {
    const ev::MappedFile mapped(*shared);
    std::vector<std::uint8_t> records;
    ev::ForEachMcapRecord(
        mapped.Bytes().subspan(8, mapped.Bytes().size() - 16), 8, std::nullopt, shared->string(),
        [&](const ev::McapRecord& record) {
          if (!records.empty() || record.opcode != static_cast<std::uint8_t>(ev::McapOpcode::kChunk)) {
            return;
          }
          const ev::McapChunk chunk = ev::ParseMcapChunk(record, shared->string());
          records = chunk.compression == "zstd" ? ev::ZstdDecompress(chunk.records, shared->string())
                                                : std::vector(chunk.records.begin(), chunk.records.end());
        });
    records.resize(std::min<std::size_t>(records.size(), 16 << 10));
    const auto cut = static_cast<std::uint32_t>(records.size());
    seeds.Add("nav2_turtlebot-chunk-head.zstd", Input(0, cut, ev::ZstdCompress(records)));
    seeds.Add("nav2_turtlebot-chunk-head.lz4", Input(kLz4, cut, Lz4(records, true)));
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t mode = data[0];
  std::span<const std::uint8_t> rest(data + 1, size - 1);
  std::optional<std::uint64_t> stated;
  if ((mode & kStated) != 0) {
    if (rest.size() < 4) return 0;
    stated = std::uint64_t{rest[0]} | std::uint64_t{rest[1]} << 8 | std::uint64_t{rest[2]} << 16 |
             std::uint64_t{rest[3]} << 24;
    rest = rest.subspan(4);
  }
  fuzz::ExpectReadOrInputError({"input.mcap"}, [&] {
    const std::vector<std::uint8_t> out =
        (mode & kLz4) != 0 ? ev::Lz4FrameDecompress(rest, kWhere, stated) : ev::ZstdDecompress(rest, kWhere, stated);
    fuzz::Require(out.size() <= ev::GzipInflateCap(rest.size()), "inflated beyond the cap");
    fuzz::Require(!stated || out.size() == *stated, "inflated to another size than the record states");
  });
  return 0;
}
