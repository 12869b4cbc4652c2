#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace slamsweep::evaluator::inline formats::inline rosbag2 {

/// Inflates one or more zstd frames (libzstd). `expected_size`, when known (an MCAP chunk states it),
/// must match. Throws InputError "`where`: ..." naming libzstd's reason for damaged or truncated data.
/// The output is capped as gzip input is (GzipInflateCap: 100 times `compressed`, at least 16 MiB): a stated
/// size (`expected_size`, the first frame header's content size) beyond the cap is an error before anything is
/// allocated, output beyond it stops inflating, and a frame may not ask for a window beyond the cap.
std::vector<std::uint8_t> ZstdDecompress(std::span<const std::uint8_t> compressed, const std::string& where,
                                         std::optional<std::uint64_t> expected_size = std::nullopt);

/// Inflates LZ4 frame-format data (liblz4's frame API, as MCAP uses it). As ZstdDecompress.
std::vector<std::uint8_t> Lz4FrameDecompress(std::span<const std::uint8_t> compressed, const std::string& where,
                                             std::optional<std::uint64_t> expected_size = std::nullopt);

/// One zstd frame of `bytes` (level 3, libzstd's default), with the content size in its header.
std::vector<std::uint8_t> ZstdCompress(std::span<const std::uint8_t> bytes);

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
