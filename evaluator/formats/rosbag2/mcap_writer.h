#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "evaluator/formats/rosbag2/mcap_records.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {

/// Writes an indexed MCAP file: the Header, Schema and Channel records, then the messages in
/// uncompressed chunks (768 KiB, as rosbag2's default) each followed by its Message Index records,
/// Data End with the data section's CRC, and a summary section (schemas, channels, statistics, chunk
/// indexes, summary offsets) whose CRC the Footer holds. Chunks carry their CRC.
class McapWriter {
 public:
  /// Creates `path` and writes the magic and the Header. Throws InputError naming the file.
  McapWriter(const std::filesystem::path& path, const std::string& profile);

  std::uint16_t AddSchema(const std::string& name, const std::string& encoding, const std::string& data);
  std::uint16_t AddChannel(std::uint16_t schema_id, const std::string& topic, const std::string& message_encoding,
                           const std::map<std::string, std::string>& metadata);
  /// Messages should come in log-time order.
  void AddMessage(std::uint16_t channel_id, std::uint64_t log_time_ns, std::span<const std::uint8_t> data);
  /// Writes the rest of the file and closes it. Throws InputError naming the file when writing fails.
  void Finish();

 private:
  void Emit(McapOpcode opcode, const std::vector<std::uint8_t>& body);
  void FlushChunk();

  std::filesystem::path path_;
  std::ofstream out_;
  std::uint64_t offset_ = 0;
  /// CRC of everything written so far (the data section's, until Data End).
  std::uint32_t crc_ = 0;
  std::vector<McapSchema> schemas_;
  std::vector<McapChannel> channels_;
  std::map<std::uint16_t, std::uint32_t> sequences_;
  std::map<std::uint16_t, std::uint64_t> message_counts_;
  std::uint64_t message_count_ = 0;
  std::uint64_t start_ns_ = 0;
  std::uint64_t end_ns_ = 0;
  // The chunk being filled: its records, and per channel (log time, offset in the records).
  std::vector<std::uint8_t> chunk_;
  std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunk_index_;
  std::uint64_t chunk_start_ns_ = 0;
  std::uint64_t chunk_end_ns_ = 0;
  std::vector<std::vector<std::uint8_t>> chunk_indexes_;
};

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
