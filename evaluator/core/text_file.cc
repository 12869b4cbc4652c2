#include "evaluator/core/text_file.h"

#include <fast_float/fast_float.h>
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <utility>

#include "evaluator/core/gzip_inflate.h"
#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline core {
namespace {

std::string QuoteField(std::string_view text) {
  constexpr std::size_t kMaxShown = 40;
  std::string shown(text.substr(0, kMaxShown));
  if (text.size() > kMaxShown) shown += "...";
  return "'" + shown + "'";
}

// zlib's streaming inflate, for data libdeflate refused: it says how far the data was good.
std::string ReadGzipStreaming(const std::filesystem::path& path) {
  struct GzCloser {
    void operator()(gzFile_s* file) const { gzclose(file); }
  };
  std::unique_ptr<gzFile_s, GzCloser> file(gzopen(path.c_str(), "rb"));
  if (!file) throw InputError(Located(path, 0, "cannot open gzip file"));
  std::string content;
  char buffer[1 << 16];
  while (true) {
    const int read = gzread(file.get(), buffer, sizeof(buffer));
    if (read < 0) {
      int code = 0;
      const char* message = gzerror(file.get(), &code);
      throw InputError(Located(path, 0, std::string("corrupt gzip data: ") + message));
    }
    if (read == 0) break;
    content.append(buffer, static_cast<std::size_t>(read));
  }
  int code = 0;
  const char* message = gzerror(file.get(), &code);
  // zlib reports a stream that ends before its trailer as Z_BUF_ERROR at end of file.
  if (code != Z_OK && code != Z_STREAM_END) {
    throw InputError(Located(path, 0,
                             std::string("truncated or corrupt gzip file (") + message + ") after " +
                                 std::to_string(content.size()) + " decompressed bytes"));
  }
  return content;
}

}  // namespace

TextFileContent ReadTextFileContent(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputError(Located(path, 0, "no such file (expected a readable regular file)"));
  }
  std::optional<MappedFile> file = MappedFile::Open(path);
  if (!file) throw InputError(Located(path, 0, "cannot open file for reading"));
  if (!HasGzipMagic(file->bytes())) return TextFileContent(std::move(*file));
  if (std::optional<std::string> text = InflateWholeGzip(file->bytes())) return TextFileContent(std::move(*text));
  return TextFileContent(ReadGzipStreaming(path));
}

std::string ReadTextFile(const std::filesystem::path& path) {
  const TextFileContent content = ReadTextFileContent(path);
  return std::string(content.text());
}

const char* ReadFiniteNumber(const char* first, const char* last, double& value) {
  const fast_float::from_chars_result quick = fast_float::from_chars(first, last, value);
  if (quick.ec != std::errc()) return nullptr;
  if (std::isnormal(value)) return quick.ptr;
  // fast_float turns overflow into infinity and underflow into zero without an error, where
  // std::from_chars reports them; a zero whose digits are all 0 is exact either way.
  bool zero_digits = value == 0.0;
  for (const char* c = first; zero_digits && c < quick.ptr && *c != 'e' && *c != 'E'; ++c) {
    zero_digits = *c < '1' || *c > '9';
  }
  if (zero_digits) return quick.ptr;
  const std::from_chars_result exact = std::from_chars(first, last, value);
  if (exact.ec != std::errc() || !std::isfinite(value)) return nullptr;
  return exact.ptr;
}

std::size_t CountLines(std::string_view content) {
  // memchr jumps from newline to newline (vectorised in glibc), several times faster than a byte loop.
  std::size_t lines = 0;
  const char* cursor = content.data();
  const char* const end = cursor + content.size();
  while (cursor < end) {
    const void* newline = std::memchr(cursor, '\n', static_cast<std::size_t>(end - cursor));
    ++lines;
    if (newline == nullptr) break;
    cursor = static_cast<const char*>(newline) + 1;
  }
  return lines;
}

std::vector<std::string_view> SplitFields(std::string_view line, std::string_view separators) {
  std::vector<std::string_view> fields;
  const bool whitespace_only = separators.find_first_not_of(" \t\r") == std::string_view::npos;
  std::size_t start = 0;
  while (start <= line.size()) {
    if (whitespace_only) {
      start = line.find_first_not_of(separators, start);
      if (start == std::string_view::npos) break;
    }
    std::size_t end = line.find_first_of(separators, start);
    if (end == std::string_view::npos) end = line.size();
    std::string_view field = line.substr(start, end - start);
    // Trim blanks around delimited fields ("1, 2" in CSV).
    const std::size_t a = field.find_first_not_of(" \t\r");
    field = a == std::string_view::npos ? std::string_view() : field.substr(a, field.find_last_not_of(" \t\r") - a + 1);
    fields.push_back(field);
    start = end + 1;
    if (end == line.size()) break;
  }
  return fields;
}

TextRecord::TextRecord(const std::filesystem::path& file, std::size_t line_number, std::vector<std::string_view> fields)
    : file_(file), line_number_(line_number), fields_(std::move(fields)) {}

std::string_view TextRecord::Text(std::size_t index) const {
  if (index >= fields_.size()) {
    Fail("expected a field " + std::to_string(index + 1) + " but the line has only " + std::to_string(fields_.size()) +
         " fields");
  }
  return fields_[index];
}

double TextRecord::Number(std::size_t index, std::string_view name) const {
  const std::string_view text = Text(index);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    Fail("field " + std::to_string(index + 1) + " (" + std::string(name) + "): expected a finite number, got " +
         QuoteField(text));
  }
  return value;
}

long long TextRecord::Integer(std::size_t index, std::string_view name) const {
  const std::string_view text = Text(index);
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    Fail("field " + std::to_string(index + 1) + " (" + std::string(name) + "): expected an integer, got " +
         QuoteField(text));
  }
  return value;
}

void TextRecord::RequireFields(std::size_t count, std::string_view layout) const {
  if (fields_.size() < count) {
    Fail("expected " + std::to_string(count) + " fields (" + std::string(layout) + "), got " +
         std::to_string(fields_.size()) + " (truncated line?)");
  }
}

void TextRecord::Fail(std::string_view message) const { throw InputError(Located(file_, line_number_, message)); }

std::string AsciiLowercase(std::string_view text) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower;
}

}  // namespace slamsweep::evaluator::inline core
