#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace slamsweep::evaluator::inline core {

/// True when `bytes` starts with the gzip magic number.
bool HasGzipMagic(std::string_view bytes);

/// The content of gzip data inflated whole by libdeflate: one member, or several concatenated
/// (as gzip writes them), bytes after the last member ignored (as zlib's gzread does). Nothing
/// when the data is not complete and valid: callers then inflate with zlib, whose streaming
/// reports how far the data was good, for the error message.
///
/// Why libdeflate: it inflates a whole buffer two to three times faster than zlib's streaming
/// inflate, and logs are read whole anyway; reading fr079 (2 MB gzip) is the budget that pays.
std::optional<std::string> InflateWholeGzip(std::string_view compressed);

}  // namespace slamsweep::evaluator::inline core
