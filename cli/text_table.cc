#include "cli/text_table.h"

#include <fmt/format.h>

#include <algorithm>

namespace slamsweep::cli {

void TextTable::Add(std::string name, double value) { Add(std::move(name), fmt::format("{:.6g}", value)); }

void TextTable::Print(std::ostream& out) const {
  std::size_t width = 0;
  for (const auto& [name, value] : rows_) width = std::max(width, name.size());
  out << title_ << "\n";
  for (const auto& [name, value] : rows_) out << fmt::format("  {:<{}}  {}\n", name, width, value);
}

}  // namespace slamsweep::cli
