#include "orchestrator/worker/run_result.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <stdexcept>
#include <utility>

namespace slamsweep::orchestrator {

void RunResult::Fail(FailureKind kind, std::string why) {
  if (failure_kind) return;
  failure_kind = kind;
  reason = std::move(why);
}

nlohmann::json ToJson(const RunResult& result) {
  nlohmann::json json;
  json["run_id"] = result.run_id;
  json["status"] = result.ok() ? "ok" : "failed";
  json["failure_kind"] =
      result.failure_kind ? nlohmann::json(std::string(FailureKindName(*result.failure_kind))) : nlohmann::json();
  json["reason"] = result.reason;
  json["exit_code"] = result.exit_code ? nlohmann::json(*result.exit_code) : nlohmann::json();
  json["signal"] = result.signal ? nlohmann::json(*result.signal) : nlohmann::json();
  json["wall_s"] = result.wall_s;
  json["cpu_s"] = result.cpu_s;
  json["peak_rss_kb"] = result.peak_rss_kb;
  json["started_at"] = result.started_at;
  json["finished_at"] = result.finished_at;
  json["command"] = result.command;
  json["outputs"] = result.outputs;
  nlohmann::json metrics = nlohmann::json::array();
  for (const FlatMetric& metric : result.metrics.metrics) metrics.push_back(ToJson(metric));
  json["metrics"] = std::move(metrics);
  json["metric_details"] = result.metrics.details;
  std::vector<std::string> warnings = result.warnings;
  warnings.insert(warnings.end(), result.metrics.warnings.begin(), result.metrics.warnings.end());
  json["warnings"] = std::move(warnings);
  return json;
}

std::string Iso8601Utc(std::int64_t seconds_since_epoch) {
  const std::time_t time = static_cast<std::time_t>(seconds_since_epoch);
  std::tm utc{};
  gmtime_r(&time, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string NowIso8601Utc() {
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return Iso8601Utc(std::chrono::duration_cast<std::chrono::seconds>(now).count());
}

void WriteJsonFileAtomically(const std::filesystem::path& file, const nlohmann::json& value) {
  const std::filesystem::path temporary = file.string() + ".tmp";
  const std::string text = value.dump(2) + "\n";
  const auto fail = [&](const char* step) {
    const std::string detail = std::strerror(errno);
    ::unlink(temporary.c_str());
    throw std::runtime_error(file.string() + ": cannot " + step + " (" + detail + ")");
  };
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("create the temporary file");
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      ::close(fd);
      fail("write");
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) {
    ::close(fd);
    fail("fsync");
  }
  if (::close(fd) != 0) fail("close");
  if (::rename(temporary.c_str(), file.c_str()) != 0) fail("rename");
  // The rename itself is durable only once the directory is synced.
  const int dir = ::open(file.parent_path().empty() ? "." : file.parent_path().c_str(), O_RDONLY | O_DIRECTORY);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

}  // namespace slamsweep::orchestrator
