// `slamsweep submit CONFIG --server URL [--wait]`: a sweep through `slamsweep serve`. With --wait it
// prints a line per finished run and exits like `slamsweep run` (0 all ok, 1 some failed, 2 a refused
// submission, 130 interrupted: Ctrl-C or SIGTERM cancels the sweep), then downloads junit.xml and the
// report.
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <map>
#include <memory>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/command.h"
#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "orchestrator/files/atomic_file.h"
#include "orchestrator/process/interruption.h"
#include "orchestrator/process/wake_up.h"
#include "orchestrator/service/auth.h"
#include "orchestrator/run/run_status.h"
#include "orchestrator/store/results_store.h"

// Last: its <resolv.h> defines `_res`, which breaks Eigen headers included after it.
#include <httplib.h>

namespace slamsweep::cli {
namespace {

using orchestrator::QueuedRunState;
using orchestrator::QueuedSweepState;
using orchestrator::ReportState;

struct SubmitOptions {
  std::string config;
  std::string server = "http://127.0.0.1:8420";
  bool wait = false;
  std::string junit;
  std::string report_dir;
  std::string token_file;
  int priority = 0;
  double poll_s = 1.0;
};

/// A refused submission or an unusable answer: exit code 2, like a bad config for `slamsweep run`.
class SubmitError : public evaluator::InputError {
 public:
  using evaluator::InputError::InputError;
};

std::string Submitter() {
  if (const char* tag = std::getenv("BUILD_TAG"); tag != nullptr && *tag != '\0') return tag;  // Jenkins
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  const char* user = std::getenv("USER");
  return fmt::format("{}@{}", user != nullptr ? user : "unknown", host);
}

class Api {
 public:
  Api(const std::string& server, std::optional<std::string> token) : client_(server), server_(server) {
    if (!client_.is_valid()) throw SubmitError("--server " + server + ": expected a URL such as http://127.0.0.1:8420");
    client_.set_connection_timeout(10);
    client_.set_tcp_nodelay(true);
    client_.set_read_timeout(120);
    if (token) headers_.emplace("Authorization", "Bearer " + *token);
    headers_.emplace("X-Slamsweep-Submitter", Submitter());
  }

  /// The answer, or nullopt when the server cannot be reached (the reason in `problem`).
  std::optional<httplib::Response> Get(const std::string& path, std::string& problem) {
    auto result = client_.Get(path, headers_);
    if (!result) {
      problem = fmt::format("cannot reach {}: {}", server_, httplib::to_string(result.error()));
      return std::nullopt;
    }
    return *result;
  }

  httplib::Result Post(const std::string& path, const std::string& body, const std::string& type) {
    return client_.Post(path, headers_, body, type);
  }

  const std::string& server() const { return server_; }

 private:
  httplib::Client client_;
  std::string server_;
  httplib::Headers headers_;
};

std::string ErrorOf(const httplib::Response& response) {
  try {
    return nlohmann::json::parse(response.body).value("error", response.body);
  } catch (const nlohmann::json::exception&) {
    return response.body;
  }
}

nlohmann::json GetJson(Api& api, const std::string& path) {
  for (;;) {
    std::string problem;
    const auto response = api.Get(path, problem);
    if (response && response->status == 200) return nlohmann::json::parse(response->body);
    if (response && response->status != 503) {
      throw SubmitError(fmt::format("GET {}: {} {}", path, response->status, ErrorOf(*response)));
    }
    // The server restarts (or drains): its queue keeps the sweep; keep asking.
    std::fprintf(stderr, "slamsweep submit: %s; retrying in 5 s\n", response ? "server draining" : problem.c_str());
    orchestrator::SleepUnlessWoken(5.0);
    if (orchestrator::InterruptionGuard::Interrupted()) return nullptr;
  }
}

void Download(Api& api, const std::string& path, const std::filesystem::path& file) {
  std::string problem;
  const auto response = api.Get(path, problem);
  if (!response) throw SubmitError(problem);
  if (response->status != 200)
    throw SubmitError(fmt::format("GET {}: {} {}", path, response->status, ErrorOf(*response)));
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  orchestrator::WriteFileAtomically(file, response->body);
}

/// The report's files into `dir`, each path checked to stay inside it.
std::size_t DownloadReport(Api& api, std::int64_t id, const std::filesystem::path& dir) {
  const nlohmann::json listing = GetJson(api, fmt::format("/api/sweeps/{}/report", id));
  if (listing.is_null()) return 0;
  const std::string base = listing.at("base").get<std::string>();
  std::size_t count = 0;
  for (const auto& file : listing.at("files")) {
    const std::filesystem::path relative = std::filesystem::path(file.get<std::string>()).lexically_normal();
    if (relative.is_absolute() || relative.empty() || *relative.begin() == "..") {
      throw SubmitError("the server listed a report file outside the report: " + relative.string());
    }
    Download(api, base + relative.generic_string(), dir / relative);
    ++count;
  }
  return count;
}

/// The state a run or sweep of the API's JSON is in; nullopt when it names none (this client
/// tolerates states it does not know, as it tolerates a missing field).
std::optional<QueuedRunState> RunState(const nlohmann::json& run) {
  return orchestrator::FindRunState(run.value("state", ""));
}
std::optional<QueuedSweepState> SweepState(const nlohmann::json& sweep) {
  return orchestrator::FindSweepState(sweep.value("state", ""));
}
std::optional<ReportState> SweepReportState(const nlohmann::json& sweep) {
  return orchestrator::FindReportState(sweep.value("report", ""));
}

/// The number of runs in `state` from a sweep's "counts".
int CountOf(const nlohmann::json& counts, QueuedRunState state) {
  return counts.value(std::string(orchestrator::ToString(state)), 0);
}

/// A line per run that ended since the last call, numbered like `slamsweep run`'s Jenkins lines.
void PrintFinishedRuns(const nlohmann::json& runs, std::set<std::string>& reported, std::ostream& out) {
  std::size_t total = runs.size(), finished = 0;
  for (const auto& run : runs) {
    const std::optional<QueuedRunState> state = RunState(run);
    if (state && orchestrator::HasResult(*state)) ++finished;
  }
  for (const auto& run : runs) {
    const std::optional<QueuedRunState> state = RunState(run);
    const std::string run_id = run.value("run_id", "");
    if (!state || !orchestrator::HasResult(*state) || !reported.insert(run_id).second) continue;
    std::string detail;
    if (state == QueuedRunState::kFailed) detail = run.value("reason", "");
    if (state == QueuedRunState::kReused) detail = fmt::format("reused from sweep {}", run["reused_from"].dump());
    if (state == QueuedRunState::kOk && run["wall_s"].is_number()) {
      detail = fmt::format("{:.1f} s", run["wall_s"].get<double>());
    }
    // The state's name padded to one width; a failure in capitals.
    const std::string label =
        state == QueuedRunState::kFailed ? std::string("FAILED") : fmt::format("{:<6}", orchestrator::ToString(*state));
    out << fmt::format("{} [{}/{}] {} {} ({})\n", orchestrator::UtcNowIso8601(), finished, total, label, run_id, detail)
        << std::flush;
  }
}

int Submit(const SubmitOptions& options, const Streams& streams) {
  const std::string text = evaluator::ReadTextFile(options.config);
  std::optional<std::string> token;
  if (!options.token_file.empty()) token = orchestrator::service::ReadTokenFile(options.token_file);
  Api api(options.server, token);
  const std::string cwd = std::filesystem::current_path().string();
  const std::string path = httplib::append_query_params(
      "/api/sweeps", {{"name", options.config}, {"base", cwd}, {"priority", std::to_string(options.priority)}});
  const httplib::Result posted = api.Post(path, text, "application/yaml");
  if (!posted) throw SubmitError(fmt::format("cannot reach {}: {}", api.server(), httplib::to_string(posted.error())));
  if (posted->status != 201) {
    streams.err << "slamsweep: error: " << ErrorOf(*posted) << " (HTTP " << posted->status << ")\n";
    return posted->status >= 500 ? 1 : 2;
  }
  const nlohmann::json submitted = nlohmann::json::parse(posted->body);
  const std::int64_t id = submitted.at("id").get<std::int64_t>();
  streams.out << fmt::format("sweep {} '{}': {} runs submitted to {} -> {}/sweeps/{}\n", id,
                             submitted.value("name", ""), submitted.at("runs").size(), api.server(), api.server(), id)
              << std::flush;
  if (!options.wait) return 0;

  // From here Ctrl-C (or Jenkins' SIGTERM on abort) cancels the sweep and exits 130, as `run` does.
  orchestrator::InterruptionGuard interruption;
  std::set<std::string> reported;
  nlohmann::json sweep;
  for (;;) {
    if (orchestrator::InterruptionGuard::Interrupted()) break;
    const nlohmann::json runs = GetJson(api, fmt::format("/api/sweeps/{}/runs", id));
    if (runs.is_null()) break;
    PrintFinishedRuns(runs.at("runs"), reported, streams.out);
    sweep = GetJson(api, fmt::format("/api/sweeps/{}", id));
    if (sweep.is_null()) break;
    const std::optional<QueuedSweepState> state = SweepState(sweep);
    const bool finished = state && orchestrator::IsFinished(*state);
    if (finished && SweepReportState(sweep) != ReportState::kWriting) break;
    orchestrator::SleepUnlessWoken(options.poll_s);
    orchestrator::TakeWakeUpRequest();
  }
  if (orchestrator::InterruptionGuard::Interrupted()) {
    streams.out << fmt::format("interrupted: cancelling sweep {}; its finished results are kept on the server\n", id);
    api.Post(fmt::format("/api/sweeps/{}/cancel", id), "", "text/plain");
    return 130;
  }
  const nlohmann::json& counts = sweep.at("counts");
  streams.out << fmt::format("sweep {} {}: {} ok, {} failed, {} reused, {} cancelled{}\n", id, sweep.value("state", ""),
                             CountOf(counts, QueuedRunState::kOk), CountOf(counts, QueuedRunState::kFailed),
                             CountOf(counts, QueuedRunState::kReused), CountOf(counts, QueuedRunState::kCancelled),
                             sweep.value("message", "").empty() ? "" : " (" + sweep.value("message", "") + ")");
  if (!options.junit.empty()) {
    Download(api, fmt::format("/api/sweeps/{}/junit.xml", id), options.junit);
    streams.out << "junit: " << options.junit << "\n";
  }
  if (!options.report_dir.empty()) {
    if (SweepReportState(sweep) == ReportState::kReady) {
      const std::size_t files = DownloadReport(api, id, options.report_dir);
      streams.out << fmt::format("report: {}/index.html ({} files)\n", options.report_dir, files);
    } else {
      streams.err << "slamsweep submit: no report to download (the report is " << sweep.value("report", "") << ")\n";
    }
  }
  const std::optional<QueuedSweepState> state = SweepState(sweep);
  if (state == QueuedSweepState::kCancelled) return 130;
  return state == QueuedSweepState::kOk && CountOf(counts, QueuedRunState::kFailed) == 0 &&
                 CountOf(counts, QueuedRunState::kCancelled) == 0
             ? 0
             : 1;
}

}  // namespace

void RegisterSubmitCommand(CLI::App& app, const Streams& streams, int& exit_code) {
  auto options = std::make_shared<SubmitOptions>();
  CLI::App* command = app.add_subcommand("submit", "submit a sweep to `slamsweep serve`; --wait follows it like `run`");
  command->add_option("CONFIG", options->config, "sweep YAML")->required();
  command->add_option("--server", options->server, "the service's URL (default http://127.0.0.1:8420)");
  command->add_flag(
      "--wait", options->wait,
      "print a line per finished run and exit like `slamsweep run` (0 ok, 1 failed runs, 130 interrupted)");
  command->add_option("--junit", options->junit, "with --wait: download the sweep's junit.xml to this file");
  command->add_option("--report", options->report_dir,
                      "with --wait: download the sweep's HTML report into this folder");
  command->add_option("--token-file", options->token_file, "file (mode 0600) with the server's bearer token");
  command->add_option("--priority", options->priority, "higher runs first (-100 to 100, default 0)")
      ->check(CLI::Range(-100, 100));
  command->add_option("--poll", options->poll_s, "seconds between progress queries with --wait")
      ->check(CLI::Range(0.05, 60.0));
  command->callback([options, &streams, &exit_code] { exit_code = Submit(*options, streams); });
}

}  // namespace slamsweep::cli
