#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace slamsweep::cli {

/// A two-column "name  value" block for people reading a terminal or a Jenkins log;
/// machines use --json instead.
class TextTable {
 public:
  explicit TextTable(std::string title) : title_(std::move(title)) {}
  void Add(std::string name, std::string value) { rows_.emplace_back(std::move(name), std::move(value)); }
  void Add(std::string name, double value);
  void Print(std::ostream& out) const;

 private:
  std::string title_;
  std::vector<std::pair<std::string, std::string>> rows_;
};

}  // namespace slamsweep::cli
