#pragma once

#include <string_view>

namespace slamsweep::evaluator::inline formats::inline map {

/// The eight bytes every PNG file starts with (PNG specification, section 5.2).
inline constexpr std::string_view kPngSignature = "\x89PNG\r\n\x1a\n";

}  // namespace slamsweep::evaluator::inline formats::inline map
