#include "evaluator/formats/rosbag2/mcap_writer.h"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {
namespace {

constexpr std::size_t kChunkSize = 768 * 1024;

/// A record body built field by field, little endian.
class Body {
 public:
  template <typename T>
  Body& Number(T value) {
    for (std::size_t i = 0; i < sizeof(T); ++i) bytes_.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
    return *this;
  }
  Body& String(const std::string& text) {
    Number(static_cast<std::uint32_t>(text.size()));
    bytes_.insert(bytes_.end(), text.begin(), text.end());
    return *this;
  }
  Body& Raw(std::span<const std::uint8_t> raw) {
    bytes_.insert(bytes_.end(), raw.begin(), raw.end());
    return *this;
  }
  /// A map or array: its byte length, then the entries `fill` writes.
  template <typename Fill>
  Body& Entries(Fill fill) {
    Body entries;
    fill(entries);
    Number(static_cast<std::uint32_t>(entries.bytes_.size()));
    return Raw(entries.bytes_);
  }
  const std::vector<std::uint8_t>& Bytes() const { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
};

std::vector<std::uint8_t> Record(McapOpcode opcode, const std::vector<std::uint8_t>& body) {
  Body record;
  record.Number(static_cast<std::uint8_t>(opcode)).Number(static_cast<std::uint64_t>(body.size())).Raw(body);
  return record.Bytes();
}

std::uint32_t Crc32(std::uint32_t crc, std::span<const std::uint8_t> bytes) {
  return static_cast<std::uint32_t>(crc32(crc, bytes.data(), static_cast<uInt>(bytes.size())));
}

}  // namespace

McapWriter::McapWriter(const std::filesystem::path& path, const std::string& profile)
    : path_(path), out_(path, std::ios::binary | std::ios::trunc) {
  if (!out_) throw InputError(Located(path, 0, "cannot create the MCAP file"));
  crc_ = static_cast<std::uint32_t>(crc32(0L, Z_NULL, 0));
  const std::span<const std::uint8_t> magic(kMcapMagic);
  out_.write(reinterpret_cast<const char*>(magic.data()), static_cast<std::streamsize>(magic.size()));
  offset_ = magic.size();
  crc_ = Crc32(crc_, magic);
  Emit(McapOpcode::kHeader, Body().String(profile).String("slamsweep").Bytes());
}

void McapWriter::Emit(McapOpcode opcode, const std::vector<std::uint8_t>& body) {
  const std::vector<std::uint8_t> record = Record(opcode, body);
  out_.write(reinterpret_cast<const char*>(record.data()), static_cast<std::streamsize>(record.size()));
  offset_ += record.size();
  crc_ = Crc32(crc_, record);
}

std::uint16_t McapWriter::AddSchema(const std::string& name, const std::string& encoding, const std::string& data) {
  const auto id = static_cast<std::uint16_t>(schemas_.size() + 1);  // 0 means "no schema"
  schemas_.push_back(McapSchema{id, name, encoding, data});
  Emit(McapOpcode::kSchema, Body().Number(id).String(name).String(encoding).String(data).Bytes());
  return id;
}

std::uint16_t McapWriter::AddChannel(std::uint16_t schema_id, const std::string& topic,
                                     const std::string& message_encoding,
                                     const std::map<std::string, std::string>& metadata) {
  const auto id = static_cast<std::uint16_t>(channels_.size() + 1);
  channels_.push_back(McapChannel{id, schema_id, topic, message_encoding, metadata});
  Body body;
  body.Number(id).Number(schema_id).String(topic).String(message_encoding).Entries([&](Body& entries) {
    for (const auto& [key, value] : metadata) entries.String(key).String(value);
  });
  Emit(McapOpcode::kChannel, body.Bytes());
  return id;
}

void McapWriter::AddMessage(std::uint16_t channel_id, std::uint64_t log_time_ns, std::span<const std::uint8_t> data) {
  if (chunk_.empty()) {
    chunk_start_ns_ = log_time_ns;
    chunk_end_ns_ = log_time_ns;
  }
  chunk_start_ns_ = std::min(chunk_start_ns_, log_time_ns);
  chunk_end_ns_ = std::max(chunk_end_ns_, log_time_ns);
  start_ns_ = message_count_ == 0 ? log_time_ns : std::min(start_ns_, log_time_ns);
  end_ns_ = std::max(end_ns_, log_time_ns);
  ++message_count_;
  ++message_counts_[channel_id];
  chunk_index_[channel_id].emplace_back(log_time_ns, chunk_.size());
  Body body;
  body.Number(channel_id).Number(++sequences_[channel_id]).Number(log_time_ns).Number(log_time_ns).Raw(data);
  const std::vector<std::uint8_t> record = Record(McapOpcode::kMessage, body.Bytes());
  chunk_.insert(chunk_.end(), record.begin(), record.end());
  if (chunk_.size() >= kChunkSize) FlushChunk();
}

void McapWriter::FlushChunk() {
  if (chunk_.empty()) return;
  const std::uint64_t chunk_start = offset_;
  const auto chunk_crc = Crc32(static_cast<std::uint32_t>(crc32(0L, Z_NULL, 0)), chunk_);
  Body chunk;
  chunk.Number(chunk_start_ns_).Number(chunk_end_ns_).Number(static_cast<std::uint64_t>(chunk_.size()));
  chunk.Number(chunk_crc).String("").Number(static_cast<std::uint64_t>(chunk_.size())).Raw(chunk_);
  Emit(McapOpcode::kChunk, chunk.Bytes());
  const std::uint64_t chunk_length = offset_ - chunk_start;
  const std::uint64_t index_start = offset_;
  std::map<std::uint16_t, std::uint64_t> index_offsets;
  for (const auto& channel_entries : chunk_index_) {
    // Not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
    const std::uint16_t channel = channel_entries.first;
    const auto& entries = channel_entries.second;
    index_offsets[channel] = offset_;
    Body index;
    index.Number(channel).Entries([&](Body& pairs) {
      for (const auto& [time, offset] : entries) pairs.Number(time).Number(offset);
    });
    Emit(McapOpcode::kMessageIndex, index.Bytes());
  }
  Body chunk_index;
  chunk_index.Number(chunk_start_ns_).Number(chunk_end_ns_).Number(chunk_start).Number(chunk_length);
  chunk_index.Entries([&](Body& offsets) {
    for (const auto& [channel, offset] : index_offsets) offsets.Number(channel).Number(offset);
  });
  chunk_index.Number(offset_ - index_start).String("");
  chunk_index.Number(static_cast<std::uint64_t>(chunk_.size())).Number(static_cast<std::uint64_t>(chunk_.size()));
  chunk_indexes_.push_back(chunk_index.Bytes());
  chunk_.clear();
  chunk_index_.clear();
}

void McapWriter::Finish() {
  FlushChunk();
  Emit(McapOpcode::kDataEnd, Body().Number(crc_).Bytes());
  // The summary: one group per record kind, each found through a Summary Offset record.
  const std::uint64_t summary_start = offset_;
  crc_ = static_cast<std::uint32_t>(crc32(0L, Z_NULL, 0));
  std::vector<std::tuple<McapOpcode, std::uint64_t, std::uint64_t>> groups;
  const auto group = [&](McapOpcode opcode, const auto& emit_all) {
    const std::uint64_t start = offset_;
    emit_all();
    if (offset_ > start) groups.emplace_back(opcode, start, offset_ - start);
  };
  group(McapOpcode::kSchema, [&] {
    for (const McapSchema& s : schemas_) {
      Emit(McapOpcode::kSchema, Body().Number(s.id).String(s.name).String(s.encoding).String(s.data).Bytes());
    }
  });
  group(McapOpcode::kChannel, [&] {
    for (const McapChannel& c : channels_) {
      Body body;
      body.Number(c.id).Number(c.schema_id).String(c.topic).String(c.message_encoding).Entries([&](Body& entries) {
        for (const auto& [key, value] : c.metadata) entries.String(key).String(value);
      });
      Emit(McapOpcode::kChannel, body.Bytes());
    }
  });
  group(McapOpcode::kStatistics, [&] {
    Body statistics;
    statistics.Number(message_count_).Number(static_cast<std::uint16_t>(schemas_.size()));
    statistics.Number(static_cast<std::uint32_t>(channels_.size())).Number(std::uint32_t{0}).Number(std::uint32_t{0});
    statistics.Number(static_cast<std::uint32_t>(chunk_indexes_.size())).Number(start_ns_).Number(end_ns_);
    statistics.Entries([&](Body& counts) {
      for (const auto& [channel, count] : message_counts_) counts.Number(channel).Number(count);
    });
    Emit(McapOpcode::kStatistics, statistics.Bytes());
  });
  group(McapOpcode::kChunkIndex, [&] {
    for (const std::vector<std::uint8_t>& index : chunk_indexes_) Emit(McapOpcode::kChunkIndex, index);
  });
  const std::uint64_t summary_offset_start = offset_;
  for (const auto& [opcode, start, length] : groups) {
    Emit(McapOpcode::kSummaryOffset,
         Body().Number(static_cast<std::uint8_t>(opcode)).Number(start).Number(length).Bytes());
  }
  // The footer's CRC covers the summary and the footer up to the CRC itself.
  Body footer_head;
  footer_head.Number(static_cast<std::uint8_t>(McapOpcode::kFooter)).Number(std::uint64_t{20});
  footer_head.Number(summary_start).Number(summary_offset_start);
  const std::uint32_t summary_crc = Crc32(crc_, footer_head.Bytes());
  Body footer = footer_head;
  footer.Number(summary_crc).Raw(std::span<const std::uint8_t>(kMcapMagic));
  out_.write(reinterpret_cast<const char*>(footer.Bytes().data()), static_cast<std::streamsize>(footer.Bytes().size()));
  out_.close();
  if (!out_) throw InputError(Located(path_, 0, "cannot write the MCAP file"));
}

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
