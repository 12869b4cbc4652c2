#include "orchestrator/matrix/plan_listing.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>

namespace slamsweep::orchestrator {

std::string FormatParameters(const nlohmann::json& parameters) {
  if (!parameters.is_object() || parameters.empty()) return "-";
  std::string text;
  for (const auto& [name, value] : parameters.items()) {
    text += (text.empty() ? "" : ",") + name + "=" + (value.is_string() ? value.get<std::string>() : value.dump());
  }
  return text;
}

std::string FormatPlan(const std::vector<RunSpec>& runs) {
  constexpr std::size_t kColumns = 7;
  using Row = std::array<std::string, kColumns>;
  std::vector<Row> rows = {Row{"run_id", "algorithm", "parameters", "sequence", "noise", "iteration", "seed"}};
  for (const RunSpec& run : runs) {
    rows.push_back(Row{run.run_id, run.algorithm.name, FormatParameters(run.algorithm.parameters),
                       run.sequence.entry.name, run.noise.name, std::to_string(run.iteration),
                       std::to_string(run.seed)});
  }
  std::array<std::size_t, kColumns> widths{};
  for (const Row& row : rows) {
    for (std::size_t i = 0; i < kColumns; ++i) widths[i] = std::max(widths[i], row[i].size());
  }
  std::string text;
  for (const Row& row : rows) {
    std::string line;
    for (std::size_t i = 0; i < kColumns; ++i) {
      line += i + 1 == kColumns ? row[i] : fmt::format("{:<{}}  ", row[i], widths[i]);
    }
    text += line + "\n";
  }
  text += fmt::format("{} run{}\n", runs.size(), runs.size() == 1 ? "" : "s");
  return text;
}

nlohmann::json PlanJson(const std::vector<RunSpec>& runs) {
  nlohmann::json array = nlohmann::json::array();
  for (const RunSpec& run : runs) array.push_back(ToJson(run));
  return array;
}

}  // namespace slamsweep::orchestrator
