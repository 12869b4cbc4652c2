#include "report/model/named_study.h"

#include <fstream>

#include "evaluator/core/input_error.h"
#include "orchestrator/store/named_study.h"

namespace slamsweep::report::inline model {

namespace {

/// summary.json's "validity" object, the rest of the file skipped while parsing; nullopt when the file or the
/// object is missing or the file is not JSON (the study is then computed from the runs).
std::optional<nlohmann::json> ReadStoredValidity(const std::filesystem::path& summary_file) {
  std::ifstream in(summary_file, std::ios::binary);
  if (!in) return std::nullopt;
  const auto keep_only_validity = [](int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    return !(depth == 1 && event == nlohmann::json::parse_event_t::key && parsed != "validity");
  };
  const nlohmann::json summary = nlohmann::json::parse(in, keep_only_validity, /*allow_exceptions=*/false);
  if (!summary.is_object() || !summary.contains("validity")) return std::nullopt;
  return summary.at("validity");
}

}  // namespace

SweepModelOptions LoadSweepModelOptions(const std::filesystem::path& result_dir) {
  SweepModelOptions options;
  options.published = LoadDefaultPublishedFigures();
  options.stored_validity = ReadStoredValidity(result_dir / "summary.json");
  const std::filesystem::path file = result_dir / orchestrator::kNamedStudyFile;
  if (!std::filesystem::exists(file)) return options;
  const orchestrator::NamedStudy named = orchestrator::ReadNamedStudy(file);
  options.named_study = named.study;
  options.named_study_source = named.source;
  return options;
}

}  // namespace slamsweep::report::inline model
