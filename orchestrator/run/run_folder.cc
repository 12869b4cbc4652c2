#include "orchestrator/run/run_folder.h"

#include <fstream>
#include <iterator>
#include <sstream>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/files/atomic_file.h"
#include "orchestrator/run/run_failure.h"
#include "orchestrator/run/run_status.h"

namespace slamsweep::orchestrator::inline run {

nlohmann::json ReadJsonFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw evaluator::InputError(fmt::format("{}: cannot read (missing or not readable)", file.string()));
  const std::string text(std::istreambuf_iterator<char>(in), {});
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw evaluator::InputError(fmt::format("{}: not valid JSON: {}", file.string(), e.what()));
  }
}

bool IsSafeRunId(std::string_view run_id) {
  if (run_id.empty() || run_id.size() > 200 || run_id.front() == '.') return false;
  for (const char c : run_id) {
    const bool allowed =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
    if (!allowed) return false;
  }
  return true;
}

std::filesystem::path RunFolder(const std::filesystem::path& output_dir, std::string_view run_id) {
  if (!IsSafeRunId(run_id)) {
    throw evaluator::InputError("run id '" + std::string(run_id) +
                                "' is not a safe folder name (expected [A-Za-z0-9_.-], not starting with '.')");
  }
  return output_dir / "runs" / std::string(run_id);
}

void WriteJsonAtomically(const std::filesystem::path& file, const nlohmann::json& value, Durability durability) {
  WriteFileAtomically(file, value.dump(2) + "\n", durability);
}

StoredResult ReadRunResult(const std::filesystem::path& run_dir) {
  const std::filesystem::path file = run_dir / "result.json";
  std::ifstream in(file);
  if (!in) return {std::nullopt, "no result.json"};
  std::stringstream text;
  text << in.rdbuf();
  try {
    nlohmann::json result = nlohmann::json::parse(text.str());
    if (!result.is_object() || !result.contains("status") || !result.contains("run_id")) {
      return {std::nullopt, file.string() + ": not a result record (expected an object with run_id and status)"};
    }
    return {std::move(result), {}};
  } catch (const nlohmann::json::exception& error) {
    return {std::nullopt, file.string() + ": " + error.what()};
  }
}

std::optional<nlohmann::json> ReadRunSpecJson(const std::filesystem::path& run_dir) {
  std::ifstream in(run_dir / "run.json");
  if (!in) return std::nullopt;
  try {
    nlohmann::json spec = nlohmann::json::parse(in);
    if (spec.is_object()) return spec;
  } catch (const nlohmann::json::exception&) {
    // An unreadable run.json adopts nothing: the run is started afresh.
  }
  return std::nullopt;
}

nlohmann::json MissingResult(const RunSpec& run, const std::string& reason, bool interrupted) {
  return {{"run_id", run.run_id},
          {"status", RunStatusName(RunStatus::kFailed)},
          {"failure_kind", FailureKindName(interrupted ? FailureKind::kInterrupted : FailureKind::kInternal)},
          {"reason", reason},
          {"exit_code", nullptr},
          {"signal", nullptr},
          {"wall_s", nullptr},
          {"cpu_s", nullptr},
          {"peak_rss_kb", nullptr},
          {"command", nlohmann::json::array()},
          {"outputs", nlohmann::json::object()},
          {"metrics", nlohmann::json::array()},
          {"metric_details", nlohmann::json::object()},
          {"warnings", nlohmann::json::array()}};
}

void RemovePartialRun(const std::filesystem::path& run_dir) {
  std::error_code ignored;
  std::filesystem::remove_all(run_dir, ignored);
}

}  // namespace slamsweep::orchestrator::inline run
