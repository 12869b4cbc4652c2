#include "report/model/table_density.h"

#include "evaluator/core/input_error.h"

namespace slamsweep::report::inline model {

std::optional<evaluator::ScanSpacing> TableScanSpacing(const std::vector<orchestrator::RunRecord>& runs,
                                                       const std::vector<std::size_t>& table_runs) {
  for (const std::size_t index : table_runs) {
    const nlohmann::json& block = runs[index].scan_spacing;
    if (!block.is_object()) continue;
    try {
      return evaluator::ScanSpacingFromJson(block);
    } catch (const evaluator::InputError&) {
      // An edited or damaged result.json: another run of the table may still say it.
    }
  }
  return std::nullopt;
}

}  // namespace slamsweep::report::inline model
