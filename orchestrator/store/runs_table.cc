#include "orchestrator/store/runs_table.h"

#include <optional>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator::inline store {

using evaluator::InputError;
using nlohmann::json;

std::string StoredJsonText(const json& value) { return value.dump(-1, ' ', false, json::error_handler_t::replace); }

json ParseStoredDocument(const std::filesystem::path& file, const std::string& run_id, const char* what,
                         const std::string& text) {
  json parsed = json::parse(text, nullptr, false);
  if (parsed.is_discarded()) {
    throw InputError(
        fmt::format("{}: run {}: its {} is not valid JSON; the database was edited or is damaged: "
                    "record the run again from its runs/ folder",
                    file.string(), run_id, what));
  }
  return parsed;
}

RunStatus StoredRunStatus(const std::filesystem::path& file, const std::string& run_id, const std::string& text) {
  const std::optional<RunStatus> status = RecordedRunStatus(text);
  if (!status) throw InputError(fmt::format("{}: runs.status of run {}: found \"{}\"", file.string(), run_id, text));
  return *status;
}

}  // namespace slamsweep::orchestrator::inline store
