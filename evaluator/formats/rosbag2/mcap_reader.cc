#include "evaluator/formats/rosbag2/mcap_reader.h"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <optional>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/rosbag2/compression.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {
namespace {

constexpr std::size_t kMagicSize = sizeof(kMcapMagic);
constexpr std::size_t kFooterRecordSize = 9 + 20;

bool HasMagicAt(std::span<const std::uint8_t> bytes, std::size_t offset) {
  return bytes.size() >= offset + kMagicSize && std::memcmp(bytes.data() + offset, kMcapMagic, kMagicSize) == 0;
}

std::uint32_t Crc32(std::span<const std::uint8_t> bytes) {
  uLong crc = crc32(0L, Z_NULL, 0);
  // zlib takes at most 4 GiB per call.
  for (std::size_t done = 0; done < bytes.size();) {
    const std::size_t part = std::min<std::size_t>(bytes.size() - done, std::size_t{1} << 30);
    crc = crc32(crc, bytes.data() + done, static_cast<uInt>(part));
    done += part;
  }
  return static_cast<std::uint32_t>(crc);
}

/// Keeps schemas, channels and message counts while streaming.
void Register(const McapRecord& record, const std::string& name, McapContents& contents) {
  switch (static_cast<McapOpcode>(record.opcode)) {
    case McapOpcode::kSchema: {
      McapSchema schema = ParseMcapSchema(record, name);
      contents.schemas[schema.id] = std::move(schema);
      break;
    }
    case McapOpcode::kChannel: {
      McapChannel channel = ParseMcapChannel(record, name);
      contents.channels[channel.id] = std::move(channel);
      break;
    }
    case McapOpcode::kMessage: {
      const McapMessage message = ParseMcapMessage(record, name);
      ++contents.message_counts[message.channel_id];
      contents.start_ns =
          contents.message_count == 0 ? message.log_time_ns : std::min(contents.start_ns, message.log_time_ns);
      contents.end_ns = std::max(contents.end_ns, message.log_time_ns);
      ++contents.message_count;
      break;
    }
    default:
      break;
  }
}

}  // namespace

McapReader::McapReader(std::span<const std::uint8_t> bytes, std::string name) : bytes_(bytes), name_(std::move(name)) {
  if (!HasMagicAt(bytes_, 0)) {
    throw InputError(
        fmt::format("{}: not an MCAP file (it does not start with the MCAP magic \\x89MCAP0\\r\\n)", name_));
  }
  if (ReadSummary()) return;
  std::vector<std::string> notes = std::move(contents_.notes);
  contents_ = McapContents();
  contents_.notes = std::move(notes);
  chunk_indexes_.clear();
  Stream([&](const McapRecord& record) {
    if (record.opcode == static_cast<std::uint8_t>(McapOpcode::kHeader) && !record.chunk_offset) {
      contents_.profile = ParseMcapHeaderProfile(record, name_);
    }
    Register(record, name_, contents_);
  });
}

bool McapReader::ReadSummary() {
  const std::size_t size = bytes_.size();
  if (size < 2 * kMagicSize + kFooterRecordSize || !HasMagicAt(bytes_, size - kMagicSize)) {
    contents_.notes.push_back(fmt::format(
        "{}: the file does not end with the MCAP footer and magic (cut short, or still being written); it was read "
        "from its start",
        name_));
    return false;
  }
  const std::size_t footer_offset = size - kMagicSize - kFooterRecordSize;
  const auto damaged = [&](const std::string& why) {
    contents_.notes.push_back(
        fmt::format("{}: the summary section is damaged ({}); the file was read from its start instead", name_, why));
    return false;
  };
  try {
    const McapRecord footer_record =
        McapRecordAt(bytes_.first(size - kMagicSize), footer_offset, 0, std::nullopt, name_);
    const McapFooter footer = ParseMcapFooter(footer_record, name_);
    if (footer.summary_start == 0) return false;  // written without a summary: stream
    const std::uint64_t summary_end = footer.summary_offset_start != 0 ? footer.summary_offset_start : footer_offset;
    if (footer.summary_start > summary_end || summary_end > footer_offset) {
      return damaged(fmt::format("the footer's summary offsets {} and {} lie outside the file", footer.summary_start,
                                 footer.summary_offset_start));
    }
    if (footer.summary_crc != 0) {
      // From the summary's start through the footer's summary_offset_start field.
      const std::span<const std::uint8_t> covered =
          bytes_.subspan(footer.summary_start, footer_offset + 9 + 16 - footer.summary_start);
      if (const std::uint32_t crc = Crc32(covered); crc != footer.summary_crc) {
        return damaged(
            fmt::format("wrong CRC: the footer states {:08x}, the summary has {:08x}", footer.summary_crc, crc));
      }
    }
    const std::span<const std::uint8_t> summary =
        bytes_.subspan(footer.summary_start, summary_end - footer.summary_start);
    std::optional<McapStatistics> statistics;
    ForEachMcapRecord(summary, footer.summary_start, std::nullopt, name_, [&](const McapRecord& record) {
      switch (static_cast<McapOpcode>(record.opcode)) {
        case McapOpcode::kStatistics:
          statistics = ParseMcapStatistics(record, name_);
          break;
        case McapOpcode::kChunkIndex:
          chunk_indexes_.push_back(ParseMcapChunkIndex(record, name_));
          break;
        default:
          Register(record, name_, contents_);
      }
    });
    // Without statistics and chunk indexes the summary cannot say where the messages are.
    if (!statistics || chunk_indexes_.empty()) return false;
    for (const McapChunkIndex& index : chunk_indexes_) {
      const bool inside = index.chunk_start >= kMagicSize && index.chunk_start < footer.summary_start &&
                          index.chunk_length <= footer.summary_start - index.chunk_start && index.chunk_length >= 9;
      if (!inside || bytes_[index.chunk_start] != static_cast<std::uint8_t>(McapOpcode::kChunk)) {
        return damaged(fmt::format("a chunk index points at byte {}, where no chunk starts", index.chunk_start));
      }
    }
    std::sort(chunk_indexes_.begin(), chunk_indexes_.end(),
              [](const McapChunkIndex& a, const McapChunkIndex& b) { return a.chunk_start < b.chunk_start; });
    contents_.profile = ParseMcapHeaderProfile(McapRecordAt(bytes_, kMagicSize, 0, std::nullopt, name_), name_);
    contents_.message_counts = statistics->channel_message_counts;
    contents_.message_count = statistics->message_count;
    contents_.start_ns = statistics->message_start_ns;
    contents_.end_ns = statistics->message_end_ns;
    contents_.indexed = true;
    return true;
  } catch (const InputError& error) {
    return damaged(error.what());
  }
}

void McapReader::Stream(const std::function<void(const McapRecord&)>& visit) const {
  std::size_t offset = kMagicSize;
  bool first = true;
  while (true) {
    if (offset >= bytes_.size()) {
      throw InputError(fmt::format(
          "{}: truncated: the file ends at byte {} without its DataEnd and Footer records (cut short, or still "
          "being written)",
          name_, bytes_.size()));
    }
    const McapRecord record = McapRecordAt(bytes_, offset, 0, std::nullopt, name_);
    if (first && record.opcode != static_cast<std::uint8_t>(McapOpcode::kHeader)) {
      throw InputError(
          fmt::format("{}: expected the Header record after the magic", DescribeMcapRecord(record, name_)));
    }
    first = false;
    switch (static_cast<McapOpcode>(record.opcode)) {
      case McapOpcode::kDataEnd: {
        const std::uint32_t stated = ParseMcapDataEnd(record, name_);
        if (stated != 0) {
          if (const std::uint32_t crc = Crc32(bytes_.first(offset)); crc != stated) {
            throw InputError(
                fmt::format("{}: wrong CRC of the data section: the record states {:08x}, the data has {:08x}",
                            DescribeMcapRecord(record, name_), stated, crc));
          }
        }
        return;
      }
      case McapOpcode::kFooter:
        return;  // a file without DataEnd
      case McapOpcode::kChunk:
        visit(record);
        ReadChunk(record, visit);
        break;
      default:
        visit(record);
    }
    offset += 9 + record.body.size();
  }
}

void McapReader::ReadChunk(const McapRecord& record, const std::function<void(const McapRecord&)>& visit) const {
  const McapChunk chunk = ParseMcapChunk(record, name_);
  const std::string where = DescribeMcapRecord(record, name_);
  std::vector<std::uint8_t> inflated;
  std::span<const std::uint8_t> records = chunk.records;
  if (chunk.compression == "zstd") {
    inflated = ZstdDecompress(chunk.records, where, chunk.uncompressed_size);
    records = inflated;
  } else if (chunk.compression == "lz4") {
    inflated = Lz4FrameDecompress(chunk.records, where, chunk.uncompressed_size);
    records = inflated;
  } else if (!chunk.compression.empty()) {
    throw InputError(
        fmt::format("{}: unknown compression '{}' (expected none, zstd or lz4)", where, chunk.compression));
  } else if (chunk.records.size() != chunk.uncompressed_size) {
    throw InputError(fmt::format("{}: uncompressed records of {} bytes, the chunk states {}", where,
                                 chunk.records.size(), chunk.uncompressed_size));
  }
  if (chunk.uncompressed_crc != 0) {
    if (const std::uint32_t crc = Crc32(records); crc != chunk.uncompressed_crc) {
      throw InputError(fmt::format("{}: wrong CRC: the chunk states {:08x}, its records have {:08x}", where,
                                   chunk.uncompressed_crc, crc));
    }
  }
  ForEachMcapRecord(records, 0, record.offset, name_, visit);
}

void McapReader::ReadMessages(const std::set<std::uint16_t>& channels,
                              const std::function<void(const McapMessage&)>& visit) const {
  const auto on_record = [&](const McapRecord& record) {
    if (record.opcode != static_cast<std::uint8_t>(McapOpcode::kMessage)) return;
    const McapMessage message = ParseMcapMessage(record, name_);
    if (channels.count(message.channel_id) > 0) visit(message);
  };
  if (!contents_.indexed) {
    Stream(on_record);
    return;
  }
  for (const McapChunkIndex& index : chunk_indexes_) {
    // A chunk whose index lists its channels is skipped when it holds none of the wanted ones.
    if (!index.message_index_offsets.empty() &&
        std::none_of(channels.begin(), channels.end(),
                     [&](std::uint16_t channel) { return index.message_index_offsets.count(channel) > 0; })) {
      continue;
    }
    const McapRecord record =
        McapRecordAt(bytes_.first(static_cast<std::size_t>(index.chunk_start + index.chunk_length)),
                     static_cast<std::size_t>(index.chunk_start), 0, std::nullopt, name_);
    ReadChunk(record, on_record);
  }
}

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
