#include "orchestrator/service/http_api.h"

#include <chrono>
#include <fstream>
#include <regex>
#include <sstream>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "orchestrator/service/api_json.h"
#include "orchestrator/service/status_page.h"
#include "orchestrator/service/submission.h"

// Last: see http_api.h.
#include <httplib.h>

namespace slamsweep::orchestrator::service {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

thread_local Clock::time_point t_request_started;

void SendJson(httplib::Response& response, int status, const nlohmann::json& body) {
  response.status = status;
  response.set_header("Cache-Control", "no-store");
  response.set_content(body.dump(2) + "\n", "application/json");
}

void SendError(httplib::Response& response, int status, const std::string& message) {
  SendJson(response, status, ErrorJson(message));
}

std::optional<std::int64_t> SweepId(const httplib::Request& request) {
  try {
    return std::stoll(request.matches[1].str());
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::string ReadFile(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

std::string ContentType(const fs::path& file) {
  static const std::map<std::string, std::string> kTypes = {{".html", "text/html; charset=utf-8"},
                                                            {".css", "text/css"},
                                                            {".png", "image/png"},
                                                            {".gif", "image/gif"},
                                                            {".svg", "image/svg+xml"},
                                                            {".json", "application/json"},
                                                            {".geojson", "application/geo+json"},
                                                            {".csv", "text/csv"},
                                                            {".xml", "application/xml"},
                                                            {".txt", "text/plain; charset=utf-8"},
                                                            {".tum", "text/plain"},
                                                            {".yaml", "text/plain"},
                                                            {".log", "text/plain"},
                                                            {".pgm", "image/x-portable-graymap"}};
  const auto found = kTypes.find(file.extension().string());
  return found == kTypes.end() ? "application/octet-stream" : found->second;
}

/// A report file's path from the URL: plain components only, resolved inside the report folder.
std::optional<fs::path> ReportFile(const fs::path& report_dir, const std::string& relative) {
  static const std::regex kSafe("[A-Za-z0-9_.,+=@-]+(/[A-Za-z0-9_.,+=@-]+)*");
  if (relative.empty() || relative.size() > 1024 || !std::regex_match(relative, kSafe)) return std::nullopt;
  for (const auto& part : fs::path(relative)) {
    if (part == ".." || part == ".") return std::nullopt;
  }
  std::error_code error;
  const fs::path root = fs::weakly_canonical(report_dir, error);
  const fs::path file = fs::weakly_canonical(report_dir / relative, error);
  if (error || !fs::is_regular_file(file)) return std::nullopt;
  const std::string root_text = root.string() + "/";
  if (file.string().compare(0, root_text.size(), root_text) != 0) return std::nullopt;
  return file;
}

QueueGauges Gauges(const Scheduler& scheduler, const ServiceOptions& options) {
  QueueGauges gauges;
  gauges.slots = options.scheduler.jobs;
  gauges.draining = scheduler.Draining();
  for (const SweepView& view : scheduler.Sweeps()) {
    gauges.runs_queued += view.counts.queued;
    gauges.runs_running += view.counts.running;
    ++gauges.sweeps_by_state[view.sweep.state];
  }
  return gauges;
}

void RegisterReads(httplib::Server& server, ApiContext& context) {
  Scheduler& scheduler = context.scheduler;
  server.Get("/healthz", [&scheduler](const httplib::Request&, httplib::Response& response) {
    response.status = scheduler.Draining() ? 503 : 200;
    response.set_content(scheduler.Draining() ? "draining\n" : "ok\n", "text/plain");
  });
  server.Get("/metrics", [&context](const httplib::Request&, httplib::Response& response) {
    response.set_content(context.metrics.Render(Gauges(context.scheduler, context.options)),
                         "text/plain; version=0.0.4; charset=utf-8");
  });
  server.Get("/", [&context](const httplib::Request&, httplib::Response& response) {
    response.set_content(RenderIndexPage(context.scheduler.Sweeps(), Gauges(context.scheduler, context.options)),
                         "text/html; charset=utf-8");
  });
  server.Get("/static/service.css", [](const httplib::Request&, httplib::Response& response) {
    response.set_content(std::string(ServiceStyleSheet()), "text/css");
  });
  server.Get(R"(/sweeps/(\d{1,18}))", [&scheduler](const httplib::Request& request, httplib::Response& response) {
    const auto id = SweepId(request);
    const auto view = id ? scheduler.Sweep(*id) : std::nullopt;
    const auto runs = id ? scheduler.Runs(*id) : std::nullopt;
    if (!view || !runs) return SendError(response, 404, "no such sweep");
    response.set_content(RenderSweepPage(*view, *runs), "text/html; charset=utf-8");
  });
  server.Get(R"(/sweeps/(\d{1,18})/report/(.+))",
             [&scheduler](const httplib::Request& request, httplib::Response& response) {
               const auto id = SweepId(request);
               const auto view = id ? scheduler.Sweep(*id) : std::nullopt;
               if (!view) return SendError(response, 404, "no such sweep");
               const auto file = ReportFile(view->sweep.result_dir / "report", request.matches[2].str());
               if (!file) return SendError(response, 404, "no such report file");
               response.set_content(ReadFile(*file), ContentType(*file));
             });
  server.Get("/api/sweeps", [&scheduler](const httplib::Request&, httplib::Response& response) {
    nlohmann::json sweeps = nlohmann::json::array();
    for (const SweepView& view : scheduler.Sweeps()) sweeps.push_back(SweepJson(view));
    SendJson(response, 200, {{"sweeps", sweeps}});
  });
  server.Get(R"(/api/sweeps/(\d{1,18}))", [&scheduler](const httplib::Request& request, httplib::Response& response) {
    const auto id = SweepId(request);
    const auto view = id ? scheduler.Sweep(*id) : std::nullopt;
    if (!view) return SendError(response, 404, "no such sweep");
    SendJson(response, 200, SweepJson(*view));
  });
  server.Get(R"(/api/sweeps/(\d{1,18})/runs)",
             [&scheduler](const httplib::Request& request, httplib::Response& response) {
               const auto id = SweepId(request);
               const auto runs = id ? scheduler.Runs(*id) : std::nullopt;
               if (!runs) return SendError(response, 404, "no such sweep");
               nlohmann::json list = nlohmann::json::array();
               for (const RunView& run : *runs) list.push_back(RunJson(run));
               SendJson(response, 200, {{"sweep", *id}, {"runs", list}});
             });
  server.Get(R"(/api/sweeps/(\d{1,18})/(junit\.xml|summary\.json|summary\.csv))",
             [&scheduler](const httplib::Request& request, httplib::Response& response) {
               const auto id = SweepId(request);
               const auto view = id ? scheduler.Sweep(*id) : std::nullopt;
               if (!view) return SendError(response, 404, "no such sweep");
               const std::string name = request.matches[2].str();
               if (!IsFinished(view->sweep.state)) {
                 return SendError(
                     response, 409,
                     fmt::format("sweep {} is {}: {} is written when it ends", *id, ToString(view->sweep.state), name));
               }
               const fs::path file = view->sweep.result_dir / name;
               if (!fs::is_regular_file(file))
                 return SendError(response, 404, name + " was not written (see the sweep's message)");
               response.set_header("Cache-Control", "no-store");
               response.set_content(ReadFile(file), ContentType(file));
             });
  server.Get(R"(/api/sweeps/(\d{1,18})/report)",
             [&scheduler](const httplib::Request& request, httplib::Response& response) {
               const auto id = SweepId(request);
               const auto view = id ? scheduler.Sweep(*id) : std::nullopt;
               if (!view) return SendError(response, 404, "no such sweep");
               if (view->report != ReportState::kReady) {
                 return SendError(response, 409, fmt::format("the report is {}", ToString(view->report)));
               }
               const fs::path root = view->sweep.result_dir / "report";
               nlohmann::json files = nlohmann::json::array();
               std::error_code error;
               for (const fs::directory_entry& entry : fs::recursive_directory_iterator(root, error)) {
                 if (entry.is_regular_file() && !entry.is_symlink())
                   files.push_back(fs::relative(entry.path(), root).string());
               }
               SendJson(response, 200,
                        {{"sweep", *id}, {"base", "/sweeps/" + std::to_string(*id) + "/report/"}, {"files", files}});
             });
}

void RegisterWrites(httplib::Server& server, ApiContext& context) {
  server.Post("/api/sweeps", [&context](const httplib::Request& request, httplib::Response& response) {
    const SubmissionAnswer answer = Submit(context, request);
    for (const auto& [name, value] : answer.headers) response.set_header(name, value);
    SendJson(response, answer.status, answer.body);
  });
  server.Post(
      R"(/api/sweeps/(\d{1,18})/cancel)", [&context](const httplib::Request& request, httplib::Response& response) {
        const auto id = SweepId(request);
        const CancelOutcome outcome = id ? context.scheduler.Cancel(*id) : CancelOutcome{};
        if (!outcome.known) return SendError(response, 404, "no such sweep");
        if (outcome.finished_as) {
          const std::string state(ToString(*outcome.finished_as));
          return SendJson(response, 409,
                          {{"error", fmt::format("sweep {} already ended ({})", *id, state)}, {"state", state}});
        }
        SendJson(response, 202, {{"id", *id}, {"state", std::string(CancellingStateName())}});
      });
}

}  // namespace

void RegisterRoutes(httplib::Server& server, ApiContext& context) {
  server.set_default_headers({{"X-Content-Type-Options", "nosniff"}, {"Referrer-Policy", "no-referrer"}});
  server.set_post_routing_handler([](const httplib::Request& request, httplib::Response& response) {
    static const std::regex kReportPath(R"(/sweeps/\d+/report/.*)");
    response.set_header("Content-Security-Policy", std::regex_match(request.path, kReportPath)
                                                       ? kReportContentSecurityPolicy
                                                       : kPageContentSecurityPolicy);
  });
  server.set_payload_max_length(context.options.limits.max_body_bytes);
  // Headers and body go out in separate writes: without TCP_NODELAY, Nagle's algorithm and the client's
  // delayed ACK hold the body back ~40 ms (measured: p99 of status reads 77 ms with it, see bench/service).
  server.set_tcp_nodelay(true);
  server.set_pre_routing_handler([&context](const httplib::Request& request, httplib::Response& response) {
    t_request_started = Clock::now();
    if (request.method == "GET" || request.method == "HEAD") return httplib::Server::HandlerResponse::Unhandled;
    const std::string header = request.get_header_value("Authorization");  // owns the text the view below sees
    const std::optional<std::string_view> authorization =
        request.has_header("Authorization") ? std::optional<std::string_view>(header) : std::nullopt;
    const BearerAuth::Verdict verdict = context.auth.Check(authorization);
    if (verdict == BearerAuth::Verdict::kAllowed) return httplib::Server::HandlerResponse::Unhandled;
    const char* why = verdict == BearerAuth::Verdict::kMissing ? "missing bearer token" : "wrong bearer token";
    // Never the token itself: only that it was missing or wrong, and who sent it.
    spdlog::warn("401 {} {} from {}: {}", request.method, request.path, request.remote_addr, why);
    response.set_header("WWW-Authenticate", "Bearer realm=\"slamsweep\"");
    SendError(response, 401, std::string(why) + ": send 'Authorization: Bearer TOKEN' (slamsweep submit --token-file)");
    return httplib::Server::HandlerResponse::Handled;
  });
  server.set_error_handler(
      httplib::Server::HandlerWithResponse([&context](const httplib::Request& request, httplib::Response& response) {
        if (!response.body.empty()) return httplib::Server::HandlerResponse::Unhandled;
        if (response.status == 413) {
          SendError(response, 413,
                    fmt::format("request body larger than this server accepts ({} bytes)",
                                context.options.limits.max_body_bytes));
        } else if (response.status == 404) {
          SendError(response, 404, "no such resource: " + request.path);
        } else {
          SendError(response, response.status,
                    fmt::format("HTTP error {} for {} {}", response.status, request.method, request.path));
        }
        return httplib::Server::HandlerResponse::Handled;
      }));
  server.set_exception_handler(
      [](const httplib::Request& request, httplib::Response& response, std::exception_ptr error) {
        std::string what = "unknown error";
        try {
          std::rethrow_exception(error);
        } catch (const std::exception& exception) {
          what = exception.what();
        } catch (...) {
        }
        spdlog::error("500 {} {}: {}", request.method, request.path, what);
        SendError(response, 500, "internal error: " + what);
      });
  server.set_logger([&context](const httplib::Request& request, const httplib::Response& response) {
    context.metrics.HttpRequest(response.status,
                                std::chrono::duration<double>(Clock::now() - t_request_started).count());
    if (request.method != "GET" || response.status >= 400) {
      spdlog::info("{} {} {} from {}", response.status, request.method, request.path, request.remote_addr);
    }
  });
  RegisterReads(server, context);
  RegisterWrites(server, context);
}

}  // namespace slamsweep::orchestrator::service
