#pragma once

#include <cstddef>
#include <cstring>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "evaluator/core/mapped_file.h"

namespace slamsweep::evaluator {

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

std::vector<std::string_view> SplitFields(std::string_view line, std::string_view separators);

/// The fast path of readers of number columns: true when `line` holds exactly values.size()
/// fields separated by spaces, tabs or CRs, each a finite number (read by std::from_chars as
/// TextRecord::Number does), stored in `values`. False for anything else; the reader then reads
/// the line as a TextRecord, whose checks say what is wrong.
bool ParseNumberFields(std::string_view line, std::span<double> values);

/// The number of lines (newline characters, plus one for a last line without one): an upper
/// bound on the records of a file, for reserving.
std::size_t CountLines(std::string_view content);

// ---- implementation of the templates ----
inline bool IsFieldBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

template <typename Visitor>
void ForEachDataLine(std::string_view content, Visitor&& visitor, std::string_view comment_prefix) {
  std::size_t line_number = 0;
  std::size_t start = 0;
  while (start < content.size()) {
    const void* newline = std::memchr(content.data() + start, '\n', content.size() - start);
    const std::size_t end =
        newline != nullptr ? static_cast<std::size_t>(static_cast<const char*>(newline) - content.data()) : content.size();
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

}  // namespace slamsweep::evaluator
