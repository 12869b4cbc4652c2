#include "evaluator/sequence/provenance_file.h"

#include <map>
#include <string>
#include <vector>

#include "evaluator/core/text_file.h"

namespace slamsweep::evaluator::inline sequence {
namespace {

constexpr std::string_view kBlanks = " \t\r";

std::string_view Trim(std::string_view text) {
  const std::size_t first = text.find_first_not_of(kBlanks);
  if (first == std::string_view::npos) return {};
  const std::size_t last = text.find_last_not_of(kBlanks);
  return text.substr(first, last - first + 1);
}

std::string FirstWord(std::string_view text) {
  text = Trim(text);
  return std::string(text.substr(0, text.find_first_of(kBlanks)));
}

using Block = std::map<std::string, std::string, std::less<>>;

/// The `Key : value` fields of every `File:` block, keyed by the file's name.
std::map<std::string, Block, std::less<>> SplitBlocks(std::string_view content) {
  std::map<std::string, Block, std::less<>> blocks;
  Block* block = nullptr;
  std::string* value = nullptr;
  std::size_t start = 0;
  while (start <= content.size()) {
    std::size_t end = content.find('\n', start);
    if (end == std::string_view::npos) end = content.size();
    const std::string_view line = content.substr(start, end - start);
    start = end + 1;
    if (Trim(line).empty()) {
      value = nullptr;
      continue;
    }
    const bool continuation = line.front() == ' ' || line.front() == '\t';
    if (continuation) {
      if (value != nullptr) *value += ' ' + std::string(Trim(line));
      continue;
    }
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos) {
      value = nullptr;
      continue;
    }
    const std::string key(Trim(line.substr(0, colon)));
    const std::string_view rest = Trim(line.substr(colon + 1));
    if (key == "File") {
      block = &blocks[FirstWord(rest)];
      value = nullptr;
      continue;
    }
    if (block == nullptr) {
      value = nullptr;
      continue;
    }
    value = &(*block)[key];
    *value = std::string(rest);
  }
  return blocks;
}

/// The value with every run of blanks made one space (the files align their columns with spaces).
std::string Field(const Block& block, std::string_view key) {
  const auto found = block.find(key);
  if (found == block.end()) return {};
  std::string collapsed;
  for (char c : found->second) {
    const bool blank = kBlanks.find(c) != std::string_view::npos;
    if (blank && (collapsed.empty() || collapsed.back() == ' ')) continue;
    collapsed += blank ? ' ' : c;
  }
  if (!collapsed.empty() && collapsed.back() == ' ') collapsed.pop_back();
  return collapsed;
}

}  // namespace

std::optional<Provenance> ParseProvenanceText(std::string_view content, std::string_view data_file_name) {
  const auto blocks = SplitBlocks(content);
  const auto found = blocks.find(data_file_name);
  if (found == blocks.end()) return std::nullopt;
  const Block& block = found->second;
  std::vector<std::string> source_parts;
  if (std::string repository = Field(block, "Source repository"); !repository.empty()) {
    source_parts.push_back(std::move(repository));
  }
  if (std::string commit = FirstWord(Field(block, "Commit (snapshot)")); !commit.empty()) {
    source_parts.push_back("commit " + commit);
  }
  if (std::string path = Field(block, "Repo path"); !path.empty()) source_parts.push_back("path " + path);
  Provenance provenance;
  for (std::size_t i = 0; i < source_parts.size(); ++i) {
    if (i > 0) provenance.source += "; ";
    provenance.source += source_parts[i];
  }
  provenance.citation = Field(block, "Original provenance");
  provenance.licence_note = Field(block, "License note");
  return provenance;
}

std::optional<Provenance> ReadProvenanceBeside(const std::filesystem::path& data_file) {
  const std::filesystem::path provenance_file = data_file.parent_path() / "PROVENANCE.txt";
  std::error_code error;
  if (!std::filesystem::is_regular_file(provenance_file, error)) return std::nullopt;
  return ParseProvenanceText(ReadTextFile(provenance_file), data_file.filename().string());
}

}  // namespace slamsweep::evaluator::inline sequence
