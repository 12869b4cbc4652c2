#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace slamsweep::evaluator::inline formats::inline rosbag2 {

/// The MCAP file format's pieces (mcap.dev/spec, version 0): the magic at both ends and records of
/// opcode (uint8) + body length (uint64) + body, little endian throughout.
inline constexpr std::uint8_t kMcapMagic[] = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};

enum class McapOpcode : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kAttachment = 0x09,
  kAttachmentIndex = 0x0A,
  kStatistics = 0x0B,
  kMetadata = 0x0C,
  kMetadataIndex = 0x0D,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};

/// "Chunk", "Message", ... or "unknown (0x42)": for messages.
std::string McapOpcodeName(std::uint8_t opcode);

struct McapSchema {
  std::uint16_t id = 0;
  std::string name;
  std::string encoding;
  std::string data;
};

struct McapChannel {
  std::uint16_t id = 0;
  std::uint16_t schema_id = 0;
  std::string topic;
  std::string message_encoding;
  std::map<std::string, std::string> metadata;
};

/// A message; `data` points into the file (or into a decompressed chunk).
struct McapMessage {
  std::uint16_t channel_id = 0;
  std::uint32_t sequence = 0;
  std::uint64_t log_time_ns = 0;
  std::uint64_t publish_time_ns = 0;
  std::span<const std::uint8_t> data;
};

struct McapChunk {
  std::uint64_t message_start_ns = 0;
  std::uint64_t message_end_ns = 0;
  std::uint64_t uncompressed_size = 0;
  std::uint32_t uncompressed_crc = 0;
  std::string compression;
  std::span<const std::uint8_t> records;
};

struct McapChunkIndex {
  std::uint64_t message_start_ns = 0;
  std::uint64_t message_end_ns = 0;
  std::uint64_t chunk_start = 0;
  std::uint64_t chunk_length = 0;
  std::map<std::uint16_t, std::uint64_t> message_index_offsets;
  std::uint64_t message_index_length = 0;
  std::string compression;
  std::uint64_t compressed_size = 0;
  std::uint64_t uncompressed_size = 0;
};

struct McapStatistics {
  std::uint64_t message_count = 0;
  std::uint16_t schema_count = 0;
  std::uint32_t channel_count = 0;
  std::uint32_t attachment_count = 0;
  std::uint32_t metadata_count = 0;
  std::uint32_t chunk_count = 0;
  std::uint64_t message_start_ns = 0;
  std::uint64_t message_end_ns = 0;
  std::map<std::uint16_t, std::uint64_t> channel_message_counts;
};

struct McapFooter {
  std::uint64_t summary_start = 0;
  std::uint64_t summary_offset_start = 0;
  std::uint32_t summary_crc = 0;
};

/// One record as it lies in the file: `offset` is where its opcode byte is, counted from the start of
/// the file, or for a record inside a chunk from the start of the chunk's records (then `chunk_offset`
/// is the chunk's place in the file).
struct McapRecord {
  std::uint8_t opcode = 0;
  std::span<const std::uint8_t> body;
  std::uint64_t offset = 0;
  std::optional<std::uint64_t> chunk_offset;
};

/// Record bodies decoded; `where` (the file) starts every error: "FILE: Chunk record at byte N: ...".
/// Each throws InputError when a field runs past the body's end or a length is impossible.
McapSchema ParseMcapSchema(const McapRecord& record, std::string_view where);
McapChannel ParseMcapChannel(const McapRecord& record, std::string_view where);
McapMessage ParseMcapMessage(const McapRecord& record, std::string_view where);
McapChunk ParseMcapChunk(const McapRecord& record, std::string_view where);
McapChunkIndex ParseMcapChunkIndex(const McapRecord& record, std::string_view where);
McapStatistics ParseMcapStatistics(const McapRecord& record, std::string_view where);
McapFooter ParseMcapFooter(const McapRecord& record, std::string_view where);
/// The Header's profile ("ros2" for rosbag2).
std::string ParseMcapHeaderProfile(const McapRecord& record, std::string_view where);
/// The Data End record's CRC of the data section (0: not computed).
std::uint32_t ParseMcapDataEnd(const McapRecord& record, std::string_view where);

/// The record starting at `offset` of `bytes`, whose first byte lies at `base` (in the file, or in
/// the chunk at `chunk_offset`). Throws InputError "`where`: truncated ...: Chunk record at byte N
/// states L bytes, M are left" when it does not fit.
McapRecord McapRecordAt(std::span<const std::uint8_t> bytes, std::size_t offset, std::uint64_t base,
                        std::optional<std::uint64_t> chunk_offset, std::string_view where);

/// Visits the records that fill `bytes` back to back (a chunk's records, the summary section).
void ForEachMcapRecord(std::span<const std::uint8_t> bytes, std::uint64_t base,
                       std::optional<std::uint64_t> chunk_offset, std::string_view where,
                       const std::function<void(const McapRecord&)>& visit);

/// "FILE: Chunk record at byte N" (or "... in the chunk at byte N").
std::string DescribeMcapRecord(const McapRecord& record, std::string_view where);

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
