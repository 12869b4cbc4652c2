#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "evaluator/validity/metric_validity.h"

namespace slamsweep::orchestrator::inline store {

/// The result directory's copy of the validity study a sweep names (validity_study: FILE): the
/// report reads it from there, so a result directory stays complete when FILE moves.
inline constexpr const char* kNamedStudyFile = "validity_study.json";

struct NamedStudy {
  std::string source;  ///< the file it was read from, as the sweep named it
  evaluator::ValidityStudy study;
  nlohmann::json json;  ///< the study as written (summary.json's "validity")
};

/// Reads a study from FILE: a sweep's summary.json or a kNamedStudyFile, both of which hold it under
/// "validity". Throws evaluator::InputError naming the file and what is wrong.
NamedStudy ReadNamedStudy(const std::filesystem::path& file);

/// Writes OUTPUT_DIR/kNamedStudyFile: {"source": ..., "validity": ...}.
void WriteNamedStudy(const NamedStudy& study, const std::filesystem::path& output_dir);

}  // namespace slamsweep::orchestrator::inline store
