#include "evaluator/core/utf8_text.h"

#include <fmt/format.h>

#include <algorithm>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline core {

std::optional<std::size_t> FirstInvalidUtf8(std::string_view text) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  std::size_t i = 0;
  while (i < text.size()) {
    const unsigned char lead = byte(i);
    if (lead < 0x80) {
      ++i;
      continue;
    }
    // The length of the sequence and the range of its second byte (which rules out overlong forms,
    // surrogates and code points beyond U+10FFFF); the other continuation bytes are 0x80-0xBF.
    std::size_t length = 0;
    unsigned char low = 0x80;
    unsigned char high = 0xBF;
    if (lead >= 0xC2 && lead <= 0xDF) {
      length = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
      length = 3;
      if (lead == 0xE0) low = 0xA0;
      if (lead == 0xED) high = 0x9F;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
      length = 4;
      if (lead == 0xF0) low = 0x90;
      if (lead == 0xF4) high = 0x8F;
    } else {
      return i;
    }
    if (i + 1 >= text.size() || byte(i + 1) < low || byte(i + 1) > high) return i;
    for (std::size_t k = 2; k < length; ++k) {
      if (i + k >= text.size() || byte(i + k) < 0x80 || byte(i + k) > 0xBF) return i;
    }
    i += length;
  }
  return std::nullopt;
}

void RequireUtf8(std::string_view text, const std::filesystem::path& file, std::string_view what) {
  const auto control = std::find_if(text.begin(), text.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return (byte < 0x20 && byte != '\t' && byte != '\n' && byte != '\r') || byte == 0x7F;
  });
  const std::optional<std::size_t> invalid = FirstInvalidUtf8(text);
  const auto control_at = static_cast<std::size_t>(control - text.begin());
  if (!invalid && control == text.end()) return;
  const std::size_t bad = invalid ? std::min(*invalid, control_at) : control_at;
  const std::string_view before = text.substr(0, bad);
  const std::size_t line = 1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
  const std::size_t last_newline = before.rfind('\n');
  const std::size_t line_start = last_newline == std::string_view::npos ? 0 : last_newline + 1;
  throw InputError(fmt::format("{}:{}:{}: {} (byte 0x{:02X}): {}", file.string(), line, bad - line_start + 1,
                               bad == control_at ? "a control character" : "not UTF-8 text",
                               static_cast<unsigned char>(text[bad]), what));
}

}  // namespace slamsweep::evaluator::inline core
