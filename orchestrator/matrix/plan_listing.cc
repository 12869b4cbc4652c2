#include "orchestrator/matrix/plan_listing.h"
#include "orchestrator/run/run_json.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <map>
#include <utility>

namespace slamsweep::orchestrator::inline matrix {

std::string FormatParameters(const nlohmann::json& parameters) {
  const std::string text = ParametersText(parameters);
  return text.empty() ? "-" : text;
}

std::string OdometryIsReferenceWarnings(const std::vector<RunSpec>& runs) {
  // One line per sequence x noise cell, naming its runs: the cell is what the user must change.
  std::map<std::pair<std::string, std::string>, std::vector<std::string>> cells;
  for (const RunSpec& run : runs) {
    if (run.odometry_is_reference) cells[{run.sequence.entry.name, run.noise.name}].push_back(run.run_id);
  }
  std::string text;
  for (const auto& [cell, ids] : cells) {
    text += fmt::format(
        "warning: {} run{} on '{}' with noise '{}' get the reference as odometry (a corrected log without odometry "
        "noise): an upper bound, not a SLAM result; add odometry noise to test SLAM: {}\n",
        ids.size(), ids.size() == 1 ? "" : "s", cell.first, cell.second, fmt::join(ids, ", "));
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

}  // namespace slamsweep::orchestrator::inline matrix
