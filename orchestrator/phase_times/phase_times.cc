#include "orchestrator/phase_times/phase_times.h"

#include <fcntl.h>
#include <unistd.h>

#include <time.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <string>

namespace slamsweep::orchestrator::inline phase_times {
namespace {

const char* TimesFile() {
  static const char* const file = [] {
    const char* value = std::getenv("SLAMSWEEP_PHASE_TIMES");
    return value != nullptr && *value != '\0' ? value : nullptr;
  }();
  return file;
}

struct Seconds {
  double wall = 0.0;
  double cpu = 0.0;
};

struct Totals {
  std::mutex mutex;
  std::map<std::string, Seconds, std::less<>> seconds;
};

double ProcessCpuSeconds() {
  timespec now{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

std::string JsonObject(const std::map<std::string, Seconds, std::less<>>& seconds, double Seconds::*field) {
  std::string text = "{";
  const char* separator = "";
  for (const auto& [phase, value] : seconds) {
    char number[32];
    std::snprintf(number, sizeof number, "%.6f", value.*field);
    text += separator + ("\"" + phase + "\": ") + number;
    separator = ", ";
  }
  return text + "}";
}

Totals& ProcessTotals() {
  static Totals totals;
  return totals;
}

}  // namespace

bool PhaseTimesEnabled() { return TimesFile() != nullptr; }

void AddPhaseTime(std::string_view phase, double wall_s, double cpu_s) {
  if (!PhaseTimesEnabled()) return;
  Totals& totals = ProcessTotals();
  const std::lock_guard lock(totals.mutex);
  auto it = totals.seconds.find(phase);
  if (it == totals.seconds.end()) it = totals.seconds.emplace(std::string(phase), Seconds{}).first;
  it->second.wall += wall_s;
  it->second.cpu += cpu_s;
}

void FlushPhaseTimes(std::string_view process_kind) {
  if (!PhaseTimesEnabled()) return;
  Totals& totals = ProcessTotals();
  std::string line;
  {
    const std::lock_guard lock(totals.mutex);
    if (totals.seconds.empty()) return;
    line = "{\"process\": \"" + std::string(process_kind) +
           "\", \"phases\": " + JsonObject(totals.seconds, &Seconds::wall) +
           ", \"cpu\": " + JsonObject(totals.seconds, &Seconds::cpu) + "}\n";
    totals.seconds.clear();
  }
  // One write with O_APPEND: the lines of concurrent workers never interleave.
  const int fd = ::open(TimesFile(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) return;
  [[maybe_unused]] const ssize_t written = ::write(fd, line.data(), line.size());
  ::close(fd);
}

PhaseTimer::PhaseTimer(std::string_view phase) : phase_(phase), enabled_(PhaseTimesEnabled()) {
  if (enabled_) {
    start_ = std::chrono::steady_clock::now();
    start_cpu_s_ = ProcessCpuSeconds();
  }
}

PhaseTimer::~PhaseTimer() {
  if (enabled_) {
    AddPhaseTime(phase_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(),
                 ProcessCpuSeconds() - start_cpu_s_);
  }
}

}  // namespace slamsweep::orchestrator::inline phase_times
