#include "orchestrator/worker/worker_service.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <filesystem>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "orchestrator/process/capped_log.h"
#include "orchestrator/process/socket_send.h"
#include "orchestrator/worker/worker.h"

namespace slamsweep::orchestrator::inline worker {
namespace {

/// The next line of `fd` without its newline; nullopt at EOF or on an error.
std::optional<std::string> ReadLine(int fd, std::string& buffer) {
  for (;;) {
    const std::size_t newline = buffer.find('\n');
    if (newline != std::string::npos) {
      std::string line = buffer.substr(0, newline);
      buffer.erase(0, newline + 1);
      return line;
    }
    char chunk[4096];
    const ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return std::nullopt;
    buffer.append(chunk, static_cast<std::size_t>(n));
  }
}

/// CPU seconds of this process and of its children it has waited for.
double CpuSeconds() {
  double total = 0.0;
  for (const int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage usage{};
    ::getrusage(who, &usage);
    total += static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
             static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
  }
  return total;
}

/// Points stdout and stderr at the run's worker.log (what a worker started for the run alone writes there).
void LogInto(const std::filesystem::path& log) {
  const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return;  // the run says what went wrong in result.json
  ::dup2(fd, STDOUT_FILENO);
  ::dup2(fd, STDERR_FILENO);
  ::close(fd);
}

/// Stops writing to the run's worker.log and leaves it as a worker started for the run alone would have:
/// capped like its log (head and tail), and gone when the worker had nothing to say (one file fewer a run).
void CloseLog(const std::filesystem::path& log) {
  const int fd = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (fd >= 0) {
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    ::close(fd);
  }
  std::error_code error;
  if (std::filesystem::file_size(log, error) == 0 && !error) {
    std::filesystem::remove(log, error);
    return;
  }
  CapLogFile(log, kWorkerLogCapBytes);
}

}  // namespace

int ServeWorkerRuns(int channel) {
  std::string buffer;
  while (const std::optional<std::string> run_dir = ReadLine(channel, buffer)) {
    if (run_dir->empty()) continue;
    const std::filesystem::path log = std::filesystem::path(*run_dir) / "worker.log";
    LogInto(log);
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = CpuSeconds();
    const int code = RunWorker(*run_dir);
    std::cout.flush();
    std::fflush(stdout);
    std::fflush(stderr);
    CloseLog(log);
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!SendAll(channel, fmt::format("{} {:.6f} {:.6f}\n", code, wall_s, CpuSeconds() - cpu_start))) return 1;
    if (code == kWorkerInterrupted) return kWorkerInterrupted;
  }
  return 0;
}

}  // namespace slamsweep::orchestrator::inline worker
