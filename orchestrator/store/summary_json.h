#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/validity/metric_validity.h"
#include "orchestrator/store/validity_table.h"
#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator::inline store {

/// One run as summary.json lists it: spec summary, status, reason, resources, flat metrics
/// ({"ape_trans": {"rmse": 0.1, ...}, "corners": {"value": 12}}), their units and the output files.
nlohmann::json SummarizeRun(const RunRecord& run);

/// The whole summary.json document: {"generated_at", "groups": [ToJson(GroupSummary)...] (one per
/// comparison group: sequence x algorithm x parameters x noise), "runs": [...], "counts": {"total", "ok", "failed"},
/// and "validity": `study` (ValidityStudyOf(runs)) with its "inputs_sha256" unless the study is empty}.
nlohmann::json BuildSummaryJson(const std::vector<RunRecord>& runs, const DigestedValidityStudy& study,
                                const std::string& generated_at);

/// Writes BuildSummaryJson(runs, study, now) to `file` atomically (readers never see a half-written file).
void WriteSummaryJson(const std::vector<RunRecord>& runs, const DigestedValidityStudy& study,
                      const std::filesystem::path& file);

}  // namespace slamsweep::orchestrator::inline store
