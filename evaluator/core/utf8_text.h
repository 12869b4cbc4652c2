#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string_view>

namespace slamsweep::evaluator::inline core {

/// The offset of the first byte of `text` that is not part of well-formed UTF-8 (RFC 3629: no overlong
/// forms, no surrogates, nothing beyond U+10FFFF), or nothing when all of it is. JSON output (nlohmann)
/// refuses anything else, so text that ends up in run identities or summaries is checked where it is read.
std::optional<std::size_t> FirstInvalidUtf8(std::string_view text);

/// Throws InputError "FILE:LINE:COLUMN: not UTF-8 text (byte 0xNN): `what`" at the first byte of `text`
/// that is not UTF-8, or "...: a control character (byte 0xNN): `what`" at the first control character
/// other than tab, line feed and carriage return (YAML allows no others; yaml-cpp reads a NUL and the
/// character after it as an escape sequence, "\0N" as the lone byte 0x85). Line and column count bytes from 1.
void RequireUtf8(std::string_view text, const std::filesystem::path& file, std::string_view what);

}  // namespace slamsweep::evaluator::inline core
