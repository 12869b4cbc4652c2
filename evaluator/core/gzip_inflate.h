#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace slamsweep::evaluator::inline core {

/// The most that gzip data of `compressed_bytes` may inflate to in slamsweep's readers: 100 times its size,
/// and never less than 16 MiB. Real logs inflate 4 to 5 times; deflate reaches 1032 times, so without a cap
/// a file of a few megabytes could make a reader hold gigabytes.
std::size_t GzipInflateCap(std::size_t compressed_bytes);

/// What a reader says when the cap is exceeded: "gzip data inflates to more than 16.0 MiB, the cap for a
/// file of 12.3 KiB (100 times its size, at least 16 MiB)".
std::string GzipInflateCapMessage(std::size_t compressed_bytes);

/// The same rule worded for other compressed data: "`format` data inflates to more than 16.0 MiB, the cap for
/// `what` of 12.3 KiB (100 times its size, at least 16 MiB)" (e.g. "zstd", "a chunk"). The zstd and lz4 chunks of
/// ROS 2 bags are capped by GzipInflateCap too.
std::string InflateCapMessage(std::string_view format, std::string_view what, std::size_t compressed_bytes);

/// True when `bytes` starts with the gzip magic number.
bool HasGzipMagic(std::string_view bytes);

/// The content of gzip data inflated whole by libdeflate: one member, or several concatenated
/// (as gzip writes them), bytes after the last member ignored (as zlib's gzread does). Nothing
/// when the data is not complete and valid: callers then inflate with zlib, whose streaming
/// reports how far the data was good, for the error message. Nothing, too, when the content would exceed
/// GzipInflateCap(compressed.size()): the streaming readers then stop at the cap with GzipInflateCapMessage.
///
/// Why libdeflate: it inflates a whole buffer two to three times faster than zlib's streaming
/// inflate, and logs are read whole anyway; reading fr079 (2 MB gzip) is the budget that pays.
std::optional<std::string> InflateWholeGzip(std::string_view compressed);

}  // namespace slamsweep::evaluator::inline core
