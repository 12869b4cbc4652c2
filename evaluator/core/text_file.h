#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace slamsweep::evaluator {

/// The whole content of a file, plain or gzip-compressed (recognised by its magic bytes,
/// not its name). Throws InputError naming the file when it is missing, unreadable or a
/// truncated/corrupt gzip stream.
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

std::vector<std::string_view> SplitFields(std::string_view line, std::string_view separators);

// ---- implementation of the template ----
template <typename Visitor>
void ForEachRecord(const std::filesystem::path& file, std::string_view content, Visitor&& visitor,
                   std::string_view separators, std::string_view comment_prefix) {
  std::size_t line_number = 0;
  std::size_t start = 0;
  while (start < content.size()) {
    std::size_t end = content.find('\n', start);
    if (end == std::string_view::npos) end = content.size();
    ++line_number;
    std::string_view line = content.substr(start, end - start);
    start = end + 1;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) continue;
    if (!comment_prefix.empty() && line.substr(first).starts_with(comment_prefix)) continue;
    visitor(TextRecord(file, line_number, SplitFields(line, separators)));
  }
}

}  // namespace slamsweep::evaluator
