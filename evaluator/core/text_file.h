#pragma once

#include <array>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "evaluator/core/mapped_file.h"

namespace slamsweep::evaluator::inline core {

/// The text of a file, plain or gzip-compressed: a plain file's bytes stay where the kernel
/// mapped them (parsers read them in place), a gzip file's are inflated into memory.
class TextFileContent {
 public:
  explicit TextFileContent(MappedFile plain) : plain_(std::move(plain)), inflated_(false) {}
  explicit TextFileContent(std::string inflated) : text_(std::move(inflated)), inflated_(true) {}

  std::string_view text() const { return inflated_ ? std::string_view(text_) : plain_->bytes(); }

 private:
  std::optional<MappedFile> plain_;
  std::string text_;
  bool inflated_;
};

/// The whole content of a file, plain or gzip-compressed (recognised by its magic bytes,
/// not its name). Throws InputError naming the file when it is missing, unreadable or a
/// truncated/corrupt gzip stream.
TextFileContent ReadTextFileContent(const std::filesystem::path& path);

/// ReadTextFileContent as a string (a copy of a plain file's bytes).
std::string ReadTextFile(const std::filesystem::path& path);

/// One line of a text file split into fields, with what is needed to report a bad field
/// precisely ("FILE:LINE: field 3 (y): expected a finite number, got 'abc'").
class TextRecord {
 public:
  TextRecord(const std::filesystem::path& file, std::size_t line_number, std::vector<std::string_view> fields);

  std::size_t line_number() const { return line_number_; }
  std::size_t size() const { return fields_.size(); }
  std::string_view Text(std::size_t index) const;
  /// A finite floating-point number; `name` describes the field in the error message.
  double Number(std::size_t index, std::string_view name) const;
  long long Integer(std::size_t index, std::string_view name) const;
  /// Throws unless the record has at least `count` fields; `layout` tells the reader what a full line holds.
  void RequireFields(std::size_t count, std::string_view layout) const;
  /// An InputError located at this record.
  [[noreturn]] void Fail(std::string_view message) const;

 private:
  const std::filesystem::path& file_;
  std::size_t line_number_;
  std::vector<std::string_view> fields_;
};

/// Calls visitor(const TextRecord&) for every non-blank line that does not start with
/// `comment_prefix` (after leading spaces). Fields are split on any of `separators`.
template <typename Visitor>
void ForEachRecord(const std::filesystem::path& file, std::string_view content, Visitor&& visitor,
                   std::string_view separators = " \t\r", std::string_view comment_prefix = "#");

/// Calls visitor(std::string_view line, std::size_t line_number) for the same lines as
/// ForEachRecord (non-blank, not a comment), without splitting them: for readers with a fast path.
template <typename Visitor>
void ForEachDataLine(std::string_view content, Visitor&& visitor, std::string_view comment_prefix = "#");

/// `text` with A-Z turned to a-z (names and extensions in files; no locale).
std::string AsciiLowercase(std::string_view text);

std::vector<std::string_view> SplitFields(std::string_view line, std::string_view separators);

/// The quick path of readers of number columns: one pass over `content` that calls
/// on_numbers(const std::array<double, N>&, std::string_view line, line_number) for each data
/// line holding exactly N fields separated by spaces, tabs or CRs, each a finite number (read by
/// std::from_chars as TextRecord::Number does), and on_other(std::string_view line, line_number)
/// for any other data line, whose reader then says what is wrong with it. Blank and comment lines are skipped as
/// ForEachRecord skips them.
template <std::size_t N, typename OnNumbers, typename OnOther>
void ForEachNumberLine(std::string_view content, OnNumbers&& on_numbers, OnOther&& on_other,
                       std::string_view comment_prefix = "#");

/// The quick path's number reader: the end of the finite number that starts at `first`, stored in
/// `value`, or nullptr when there is none. Accepts and gives exactly what std::from_chars does
/// (TextRecord::Number), in a third of its time: fast_float reads the usual numbers, and zeros
/// written with a non-zero digit, subnormals, infinities and NaNs are left to std::from_chars.
const char* ReadFiniteNumber(const char* first, const char* last, double& value);

/// How many lines `content` has (a last line without its newline counts): what a reader of one record per
/// line reserves, so that its vectors are allocated once, at their final size.
std::size_t CountLines(std::string_view content);

// ---- implementation of the templates ----
inline bool IsFieldBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

template <typename Visitor>
void ForEachDataLine(std::string_view content, Visitor&& visitor, std::string_view comment_prefix) {
  std::size_t line_number = 0;
  std::size_t start = 0;
  while (start < content.size()) {
    const void* newline = std::memchr(content.data() + start, '\n', content.size() - start);
    const std::size_t end = newline != nullptr
                                ? static_cast<std::size_t>(static_cast<const char*>(newline) - content.data())
                                : content.size();
    ++line_number;
    const std::string_view line = content.substr(start, end - start);
    start = end + 1;
    std::size_t first = 0;
    while (first < line.size() && IsFieldBlank(line[first])) ++first;
    if (first == line.size()) continue;
    if (!comment_prefix.empty() && line.substr(first).starts_with(comment_prefix)) continue;
    visitor(line, line_number);
  }
}

template <std::size_t N, typename OnNumbers, typename OnOther>
void ForEachNumberLine(std::string_view content, OnNumbers&& on_numbers, OnOther&& on_other,
                       std::string_view comment_prefix) {
  const char* const begin = content.data();
  const char* const end = begin + content.size();
  const auto line_end_from = [end](const char* from) {
    const void* newline = std::memchr(from, '\n', static_cast<std::size_t>(end - from));
    return newline != nullptr ? static_cast<const char*>(newline) : end;
  };
  std::array<double, N> values{};
  std::size_t line_number = 0;
  const char* cursor = begin;
  while (cursor < end) {
    ++line_number;
    const char* const line_start = cursor;
    while (cursor < end && IsFieldBlank(*cursor)) ++cursor;
    if (cursor == end) break;
    if (*cursor == '\n') {
      ++cursor;
      continue;
    }
    if (!comment_prefix.empty() &&
        std::string_view(cursor, static_cast<std::size_t>(end - cursor)).starts_with(comment_prefix)) {
      const char* line_end = line_end_from(cursor);
      cursor = line_end == end ? end : line_end + 1;
      continue;
    }
    std::size_t count = 0;
    bool numbers = true;
    while (true) {
      if (count == N) {
        numbers = false;
        break;
      }
      const char* stop = ReadFiniteNumber(cursor, end, values[count]);
      if (stop == nullptr || (stop != end && !IsFieldBlank(*stop) && *stop != '\n')) {
        numbers = false;
        break;
      }
      ++count;
      cursor = stop;
      while (cursor < end && IsFieldBlank(*cursor)) ++cursor;
      if (cursor == end || *cursor == '\n') break;
    }
    if (numbers && count == N) {
      on_numbers(values, std::string_view(line_start, static_cast<std::size_t>(cursor - line_start)), line_number);
      if (cursor < end) ++cursor;
      continue;
    }
    const char* line_end = line_end_from(line_start);
    on_other(std::string_view(line_start, static_cast<std::size_t>(line_end - line_start)), line_number);
    cursor = line_end == end ? end : line_end + 1;
  }
}

template <typename Visitor>
void ForEachRecord(const std::filesystem::path& file, std::string_view content, Visitor&& visitor,
                   std::string_view separators, std::string_view comment_prefix) {
  ForEachDataLine(
      content,
      [&](std::string_view line, std::size_t line_number) {
        visitor(TextRecord(file, line_number, SplitFields(line, separators)));
      },
      comment_prefix);
}

}  // namespace slamsweep::evaluator::inline core
