#include "orchestrator/service/submission.h"

#include <optional>
#include <regex>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/config/input_policy.h"
#include "orchestrator/matrix/expand_matrix.h"
#include "orchestrator/service/api_json.h"
#include "orchestrator/service/http_api.h"
#include "orchestrator/store/named_study.h"

// Last: see http_api.h.
#include <httplib.h>

namespace slamsweep::orchestrator::service {
namespace {

namespace fs = std::filesystem;

SubmissionAnswer Error(int status, const std::string& message) { return {status, ErrorJson(message), {}}; }

bool HasControlCharacters(std::string_view text) {
  return std::any_of(text.begin(), text.end(),
                     [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
}

bool IsPlainName(std::string_view text) {
  return !text.empty() && text.size() <= 64 && text.front() != '.' &&
         text.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.-") ==
             std::string_view::npos;
}

/// Who submitted, for the page: printable ASCII, at most 100 characters.
std::string Submitter(const httplib::Request& request) {
  std::string submitter = request.get_header_value("X-Slamsweep-Submitter");
  if (submitter.empty()) submitter = "anonymous@" + request.remote_addr;
  if (submitter.size() > 100) submitter.resize(100);
  for (char& c : submitter) {
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '_';
  }
  return submitter;
}

/// Every occurrence of `from` in `text` replaced by `to`.
std::string ReplaceAll(std::string text, const std::string& from, const std::string& to) {
  if (from.empty()) return text;
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

}  // namespace

SubmissionAnswer Submit(ApiContext& context, const httplib::Request& request) {
  const ServiceOptions& options = context.options;
  if (context.scheduler.Draining()) {
    return {503,
            ErrorJson("the server is draining (shutting down): submit again once it is back"),
            {{"Retry-After", "60"}}};
  }
  if (context.scheduler.UnfinishedSweeps() >= options.limits.max_unfinished_sweeps) {
    return {429,
            ErrorJson(fmt::format("{} sweeps are queued or running, the most this server holds; submit again later",
                                  options.limits.max_unfinished_sweeps)),
            {{"Retry-After", "60"}}};
  }
  int priority = 0;
  if (request.has_param("priority")) {
    const std::string text = request.get_param_value("priority");
    static const std::regex kPriority("-?[0-9]{1,3}");
    if (!std::regex_match(text, kPriority) || std::stoi(text) < -100 || std::stoi(text) > 100) {
      return Error(400, "priority: expected a whole number from -100 to 100, got '" + text.substr(0, 40) + "'");
    }
    priority = std::stoi(text);
  }
  const std::string name = request.has_param("name") ? request.get_param_value("name") : "sweep.yaml";
  if (name.empty() || name.size() > 255 || HasControlCharacters(name) || name.back() == '/') {
    return Error(400, "name: expected the sweep file's name (1 to 255 characters, no control characters)");
  }
  fs::path base = options.data_dir / "submitted";
  if (request.has_param("base")) {
    const std::string text = request.get_param_value("base");
    if (text.empty() || text.size() > 4096 || HasControlCharacters(text) || text.front() != '/') {
      return Error(400, "base: expected the absolute folder of the sweep file");
    }
    base = text;
  }
  // Relative paths of the file are anchored where the submitter's copy lives; messages name the file as
  // the submitter typed it, so they read exactly as `slamsweep plan NAME` prints them there.
  const fs::path anchored =
      fs::path(name).is_absolute() ? fs::path(name).lexically_normal() : (base / name).lexically_normal();
  PlanLimits limits;
  limits.policy.allowed_roots = options.allowed_roots;
  limits.policy.allow_commands = options.allow_commands;
  limits.policy.allow_network = options.allow_network;
  limits.max_runs = options.limits.max_runs_per_sweep;
  PlannedSweep planned;
  std::optional<NamedStudy> named_study;
  try {
    planned = context.planner(request.body, anchored, limits);
    if (!planned.validity_study.empty()) named_study = ReadNamedStudy(planned.validity_study);
  } catch (const PolicyError& error) {
    return Error(403, ReplaceAll(error.what(), anchored.string(), name));
  } catch (const MatrixTooLargeError& error) {
    return Error(413, ReplaceAll(error.what(), anchored.string(), name));
  } catch (const evaluator::InputError& error) {
    return Error(400, ReplaceAll(error.what(), anchored.string(), name));
  }
  // Names become run ids, report file names, JUnit names and page text: a shared service takes only
  // plain ones, so that no submitted name carries markup or shell syntax anywhere.
  for (const RunSpec& run : planned.runs) {
    for (const auto& [what, value] : {std::pair<const char*, const std::string&>{"algorithm", run.algorithm.name},
                                      {"sequence", run.sequence.entry.name},
                                      {"noise setting", run.noise.name}}) {
      if (!IsPlainName(value)) {
        return Error(400, fmt::format("{}: {} name '{}': expected letters, digits, '_', '.' or '-' (this server's rule "
                                      "for names)",
                                      name, what, value.substr(0, 80)));
      }
    }
  }
  for (RunSpec& run : planned.runs) run.allow_unisolated = options.allow_unisolated;
  QueuedSweep sweep;
  sweep.name = planned.name;
  sweep.config_name = name;
  sweep.config_text = request.body;
  sweep.submitter = Submitter(request);
  sweep.priority = priority;
  sweep = context.scheduler.Submit(std::move(sweep), planned.runs);
  if (named_study) {
    // The report of the sweep reads the study it names from its result directory, as after `slamsweep run`.
    std::error_code ignored;
    fs::create_directories(sweep.result_dir, ignored);
    WriteNamedStudy(*named_study, sweep.result_dir);
  }
  nlohmann::json run_ids = nlohmann::json::array();
  for (const RunSpec& run : planned.runs) run_ids.push_back(run.run_id);
  const std::string location = "/api/sweeps/" + std::to_string(sweep.id);
  return {201,
          {{"id", sweep.id},
           {"name", sweep.name},
           {"state", std::string(ToString(sweep.state))},
           {"priority", sweep.priority},
           {"runs", run_ids},
           {"links", {{"self", location}, {"page", "/sweeps/" + std::to_string(sweep.id)}}}},
          {{"Location", location}}};
}

}  // namespace slamsweep::orchestrator::service
