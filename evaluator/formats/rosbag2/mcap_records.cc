#include "evaluator/formats/rosbag2/mcap_records.h"

#include <fmt/format.h>

#include <cstring>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {
namespace {

constexpr std::size_t kRecordPrefix = 9;  // opcode + length

/// Little-endian fields of one record body, each checked against the body's end.
class BodyReader {
 public:
  BodyReader(const McapRecord& record, std::string_view where) : record_(record), where_(where) {}

  template <typename T>
  T Number(const char* field) {
    T value = 0;
    const std::span<const std::uint8_t> raw = Take(sizeof(T), field);
    for (std::size_t i = 0; i < sizeof(T); ++i) value |= static_cast<T>(static_cast<T>(raw[i]) << (8 * i));
    return value;
  }
  std::string String(const char* field) {
    const auto length = Number<std::uint32_t>(field);
    const std::span<const std::uint8_t> raw = Take(length, field);
    return std::string(reinterpret_cast<const char*>(raw.data()), raw.size());
  }
  std::span<const std::uint8_t> Bytes64(const char* field) { return Take(Number<std::uint64_t>(field), field); }
  std::span<const std::uint8_t> Rest() { return Take(record_.body.size() - offset_, "data"); }
  /// A map's or array's body: its uint32 byte length, then that many bytes read by `read_entry`.
  template <typename ReadEntry>
  void Entries(const char* field, ReadEntry read_entry) {
    const auto length = Number<std::uint32_t>(field);
    const std::size_t start = offset_;
    Take(length, field);  // the entries fit in the body
    const std::size_t end = offset_;
    offset_ = start;
    while (offset_ < end) read_entry();
    if (offset_ != end) Fail(fmt::format("{}: entries run past the {} bytes the field states", field, length));
  }
  [[noreturn]] void Fail(const std::string& message) const {
    throw InputError(DescribeMcapRecord(record_, where_) + ": " + message);
  }

 private:
  std::span<const std::uint8_t> Take(std::uint64_t size, const char* field) {
    if (size > record_.body.size() - offset_) {
      Fail(fmt::format("field {} ({} bytes at byte {} of the record) runs past its {}-byte body", field, size,
                       offset_ + kRecordPrefix, record_.body.size()));
    }
    const std::span<const std::uint8_t> taken = record_.body.subspan(offset_, static_cast<std::size_t>(size));
    offset_ += static_cast<std::size_t>(size);
    return taken;
  }

  const McapRecord& record_;
  std::string_view where_;
  std::size_t offset_ = 0;
};

void RequireOpcode(const McapRecord& record, McapOpcode opcode, std::string_view where) {
  if (record.opcode != static_cast<std::uint8_t>(opcode)) {
    throw InputError(fmt::format("{}: expected a {} record", DescribeMcapRecord(record, where),
                                 McapOpcodeName(static_cast<std::uint8_t>(opcode))));
  }
}

}  // namespace

std::string McapOpcodeName(std::uint8_t opcode) {
  static constexpr const char* kNames[] = {"Header",        "Footer",          "Schema",       "Channel",
                                           "Message",       "Chunk",           "MessageIndex", "ChunkIndex",
                                           "Attachment",    "AttachmentIndex", "Statistics",   "Metadata",
                                           "MetadataIndex", "SummaryOffset",   "DataEnd"};
  if (opcode >= 0x01 && opcode <= 0x0F) return kNames[opcode - 1];
  return fmt::format("unknown (0x{:02x})", opcode);
}

std::string DescribeMcapRecord(const McapRecord& record, std::string_view where) {
  if (record.chunk_offset) {
    return fmt::format("{}: {} record at byte {} of the chunk at byte {}", where, McapOpcodeName(record.opcode),
                       record.offset, *record.chunk_offset);
  }
  return fmt::format("{}: {} record at byte {}", where, McapOpcodeName(record.opcode), record.offset);
}

McapRecord McapRecordAt(std::span<const std::uint8_t> bytes, std::size_t offset, std::uint64_t base,
                        std::optional<std::uint64_t> chunk_offset, std::string_view where) {
  McapRecord record;
  record.offset = base + offset;
  record.chunk_offset = chunk_offset;
  const std::string place = chunk_offset
                                ? fmt::format("at byte {} of the chunk at byte {}", record.offset, *chunk_offset)
                                : fmt::format("at byte {}", record.offset);
  if (bytes.size() - offset < kRecordPrefix) {
    throw InputError(fmt::format("{}: truncated: {} bytes {} cannot hold a record (opcode and length, 9 bytes)", where,
                                 bytes.size() - offset, place));
  }
  record.opcode = bytes[offset];
  std::uint64_t length = 0;
  for (std::size_t i = 0; i < 8; ++i) length |= std::uint64_t{bytes[offset + 1 + i]} << (8 * i);
  const std::size_t left = bytes.size() - offset - kRecordPrefix;
  if (length > left) {
    throw InputError(fmt::format("{}: truncated: {} record {} states {} bytes, {} are left", where,
                                 McapOpcodeName(record.opcode), place, length, left));
  }
  record.body = bytes.subspan(offset + kRecordPrefix, static_cast<std::size_t>(length));
  return record;
}

void ForEachMcapRecord(std::span<const std::uint8_t> bytes, std::uint64_t base,
                       std::optional<std::uint64_t> chunk_offset, std::string_view where,
                       const std::function<void(const McapRecord&)>& visit) {
  std::size_t offset = 0;
  while (offset < bytes.size()) {
    const McapRecord record = McapRecordAt(bytes, offset, base, chunk_offset, where);
    visit(record);
    offset += kRecordPrefix + record.body.size();
  }
}

McapSchema ParseMcapSchema(const McapRecord& record, std::string_view where) {
  RequireOpcode(record, McapOpcode::kSchema, where);
  BodyReader reader(record, where);
  McapSchema schema;
  schema.id = reader.Number<std::uint16_t>("id");
  schema.name = reader.String("name");
  schema.encoding = reader.String("encoding");
  schema.data = reader.String("data");
  return schema;
}

McapChannel ParseMcapChannel(const McapRecord& record, std::string_view where) {
  RequireOpcode(record, McapOpcode::kChannel, where);
  BodyReader reader(record, where);
  McapChannel channel;
  channel.id = reader.Number<std::uint16_t>("id");
  channel.schema_id = reader.Number<std::uint16_t>("schema_id");
  channel.topic = reader.String("topic");
  channel.message_encoding = reader.String("message_encoding");
  reader.Entries("metadata", [&] {
    std::string key = reader.String("metadata key");
    channel.metadata[std::move(key)] = reader.String("metadata value");
  });
  return channel;
}

McapMessage ParseMcapMessage(const McapRecord& record, std::string_view where) {
  RequireOpcode(record, McapOpcode::kMessage, where);
  BodyReader reader(record, where);
  McapMessage message;
  message.channel_id = reader.Number<std::uint16_t>("channel_id");
  message.sequence = reader.Number<std::uint32_t>("sequence");
  message.log_time_ns = reader.Number<std::uint64_t>("log_time");
  message.publish_time_ns = reader.Number<std::uint64_t>("publish_time");
  message.data = reader.Rest();
  return message;
}

McapChunk ParseMcapChunk(const McapRecord& record, std::string_view where) {
  RequireOpcode(record, McapOpcode::kChunk, where);
  BodyReader reader(record, where);
  McapChunk chunk;
  chunk.message_start_ns = reader.Number<std::uint64_t>("message_start_time");
  chunk.message_end_ns = reader.Number<std::uint64_t>("message_end_time");
  chunk.uncompressed_size = reader.Number<std::uint64_t>("uncompressed_size");
  chunk.uncompressed_crc = reader.Number<std::uint32_t>("uncompressed_crc");
  chunk.compression = reader.String("compression");
  chunk.records = reader.Bytes64("records");
  return chunk;
}

McapChunkIndex ParseMcapChunkIndex(const McapRecord& record, std::string_view where) {
  RequireOpcode(record, McapOpcode::kChunkIndex, where);
  BodyReader reader(record, where);
  McapChunkIndex index;
  index.message_start_ns = reader.Number<std::uint64_t>("message_start_time");
  index.message_end_ns = reader.Number<std::uint64_t>("message_end_time");
  index.chunk_start = reader.Number<std::uint64_t>("chunk_start_offset");
  index.chunk_length = reader.Number<std::uint64_t>("chunk_length");
  reader.Entries("message_index_offsets", [&] {
    const auto channel = reader.Number<std::uint16_t>("message_index_offsets channel");
    index.message_index_offsets[channel] = reader.Number<std::uint64_t>("message_index_offsets offset");
  });
  index.message_index_length = reader.Number<std::uint64_t>("message_index_length");
  index.compression = reader.String("compression");
  index.compressed_size = reader.Number<std::uint64_t>("compressed_size");
  index.uncompressed_size = reader.Number<std::uint64_t>("uncompressed_size");
  return index;
}

McapStatistics ParseMcapStatistics(const McapRecord& record, std::string_view where) {
  RequireOpcode(record, McapOpcode::kStatistics, where);
  BodyReader reader(record, where);
  McapStatistics statistics;
  statistics.message_count = reader.Number<std::uint64_t>("message_count");
  statistics.schema_count = reader.Number<std::uint16_t>("schema_count");
  statistics.channel_count = reader.Number<std::uint32_t>("channel_count");
  statistics.attachment_count = reader.Number<std::uint32_t>("attachment_count");
  statistics.metadata_count = reader.Number<std::uint32_t>("metadata_count");
  statistics.chunk_count = reader.Number<std::uint32_t>("chunk_count");
  statistics.message_start_ns = reader.Number<std::uint64_t>("message_start_time");
  statistics.message_end_ns = reader.Number<std::uint64_t>("message_end_time");
  reader.Entries("channel_message_counts", [&] {
    const auto channel = reader.Number<std::uint16_t>("channel_message_counts channel");
    statistics.channel_message_counts[channel] = reader.Number<std::uint64_t>("channel_message_counts count");
  });
  return statistics;
}

McapFooter ParseMcapFooter(const McapRecord& record, std::string_view where) {
  RequireOpcode(record, McapOpcode::kFooter, where);
  BodyReader reader(record, where);
  McapFooter footer;
  footer.summary_start = reader.Number<std::uint64_t>("summary_start");
  footer.summary_offset_start = reader.Number<std::uint64_t>("summary_offset_start");
  footer.summary_crc = reader.Number<std::uint32_t>("summary_crc");
  return footer;
}

std::string ParseMcapHeaderProfile(const McapRecord& record, std::string_view where) {
  RequireOpcode(record, McapOpcode::kHeader, where);
  BodyReader reader(record, where);
  return reader.String("profile");
}

std::uint32_t ParseMcapDataEnd(const McapRecord& record, std::string_view where) {
  RequireOpcode(record, McapOpcode::kDataEnd, where);
  BodyReader reader(record, where);
  return reader.Number<std::uint32_t>("data_section_crc");
}

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
