#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "evaluator/formats/rosbag2/mcap_records.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {

/// What an MCAP file holds.
struct McapContents {
  std::string profile;
  std::map<std::uint16_t, McapSchema> schemas;
  std::map<std::uint16_t, McapChannel> channels;
  /// Messages per channel.
  std::map<std::uint16_t, std::uint64_t> message_counts;
  std::uint64_t message_count = 0;
  /// Log times of the first and last message (0 when there are none).
  std::uint64_t start_ns = 0;
  std::uint64_t end_ns = 0;
  /// Read through the summary section's index (schemas, channels, statistics, chunk indexes);
  /// otherwise the whole file was streamed.
  bool indexed = false;
  /// Why the index was not used, when the file has one that is damaged.
  std::vector<std::string> notes;
};

/// Reads an MCAP file held in memory (mapped or inflated). With a sound summary section (Statistics,
/// Chunk Indexes) the contents come from it and only the chunks holding wanted channels are inflated;
/// without one, or when it is damaged (a bad CRC, a record that does not parse, a chunk index that
/// points at no chunk), the file is streamed from its start, as a file still being written must be.
/// Chunks may be uncompressed, zstd or lz4; their CRCs are checked when non-zero, and so is the data
/// section's CRC when streaming. Errors are InputErrors naming `name` and the record's byte offset.
class McapReader {
 public:
  /// `bytes` must outlive the reader. Throws InputError when the file does not start with the MCAP
  /// magic or its records cannot be read (truncated, a wrong CRC, an unknown compression).
  McapReader(std::span<const std::uint8_t> bytes, std::string name);

  const McapContents& Contents() const { return contents_; }

  /// Calls `visit` for each message of `channels`, in file order (chunk by chunk).
  void ReadMessages(const std::set<std::uint16_t>& channels,
                    const std::function<void(const McapMessage&)>& visit) const;

 private:
  /// Fills contents_ from the summary section; false (and a note) when it is missing or damaged.
  bool ReadSummary();
  /// Walks the data section from the start: every record, chunks inflated.
  void Stream(const std::function<void(const McapRecord&)>& visit) const;
  void ReadChunk(const McapRecord& record, const std::function<void(const McapRecord&)>& visit) const;

  std::span<const std::uint8_t> bytes_;
  std::string name_;
  McapContents contents_;
  std::vector<McapChunkIndex> chunk_indexes_;
};

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
