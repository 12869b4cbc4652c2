#include "orchestrator/sweep/status.h"

#include <unistd.h>

#include <cstdlib>
#include <ostream>
#include <string_view>

#include <fmt/format.h>
#include <spdlog/logger.h>
#include <spdlog/sinks/ostream_sink.h>

namespace slamsweep::orchestrator::inline sweep {
namespace {

std::string FormatDuration(double seconds) {
  const long total = static_cast<long>(seconds + 0.5);
  if (total < 60) return fmt::format("{}s", total);
  if (total < 3600) return fmt::format("{}m{:02}s", total / 60, total % 60);
  return fmt::format("{}h{:02}m", total / 3600, (total % 3600) / 60);
}

/// Shared counting, so both displays agree on the numbers.
class CountingStatus : public Status {
 public:
  CountingStatus(std::ostream& out, std::size_t slots) : out_(out), slots_(slots) {}

  void Planned(std::size_t to_run, std::size_t already_done) override {
    total_ = to_run;
    start_ = std::chrono::steady_clock::now();
    Line(fmt::format("{} runs to do, {} already done by an earlier sweep", to_run, already_done));
  }
  void Started(const std::string& run_id) override {
    ++running_;
    last_ = run_id;
    Redraw();
  }
  void Finished(const FinishedRun& run) override {
    if (running_ > 0) --running_;
    ++finished_;
    if (!run.ok) ++failed_;
    Report(run);
    Redraw();
  }
  void Message(const std::string& text) override { Line(text); }

 protected:
  virtual void Line(const std::string& text) = 0;
  virtual void Report(const FinishedRun& run) = 0;
  virtual void Redraw() {}

  std::string Progress() const {
    const std::string eta = EstimateRemaining(finished_, total_, slots_, std::chrono::steady_clock::now() - start_);
    return fmt::format("[{}/{}] {} running, {} failed{}", finished_, total_, running_, failed_,
                       eta.empty() ? "" : ", ETA " + eta);
  }

  std::ostream& out_;
  std::size_t slots_;
  std::size_t total_ = 0, finished_ = 0, running_ = 0, failed_ = 0;
  std::string last_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// Jenkins console: whole lines only, each with a UTC timestamp (spdlog, flushed per line so
/// the console shows progress while the sweep runs).
class PlainStatus final : public CountingStatus {
 public:
  PlainStatus(std::ostream& out, std::size_t slots)
      : CountingStatus(out, slots),
        logger_("slamsweep", std::make_shared<spdlog::sinks::ostream_sink_st>(out, /*force_flush=*/true)) {
    logger_.set_pattern("%Y-%m-%dT%H:%M:%SZ %v", spdlog::pattern_time_type::utc);
  }
  void Done() override { logger_.flush(); }

 private:
  void Line(const std::string& text) override { logger_.info(text); }
  void Report(const FinishedRun& run) override {
    Line(fmt::format("{} {} {} ({})", Progress(), run.ok ? "ok    " : "FAILED", run.run_id,
                     run.ok ? FormatDuration(run.wall_s) : run.reason));
  }

  spdlog::logger logger_;
};

/// A person at a terminal: one live line, failures kept above it.
class LiveStatus final : public CountingStatus {
 public:
  using CountingStatus::CountingStatus;
  void Done() override { out_ << "\r\x1b[K" << std::flush; }

 private:
  void Line(const std::string& text) override {
    out_ << "\r\x1b[K" << text << "\n";
    Redraw();
  }
  void Report(const FinishedRun& run) override {
    if (!run.ok) out_ << "\r\x1b[KFAILED " << run.run_id << ": " << run.reason << "\n";
  }
  void Redraw() override {
    std::string line = Progress() + "  " + last_;
    // A wrapped line cannot be redrawn with \r: keep it within a common terminal width.
    if (line.size() > 100) line.resize(100);
    out_ << "\r\x1b[K" << line << std::flush;
  }
};

}  // namespace

std::string EstimateRemaining(std::size_t finished, std::size_t total, std::size_t slots,
                              std::chrono::steady_clock::duration elapsed) {
  if (finished == 0 || finished >= total || slots == 0) return {};
  const double elapsed_s = std::chrono::duration<double>(elapsed).count();
  // Throughput so far already includes the parallelism actually achieved.
  const double per_run_s = elapsed_s / static_cast<double>(finished);
  return FormatDuration(per_run_s * static_cast<double>(total - finished));
}

std::unique_ptr<Status> MakeStatus(std::ostream& out, bool smart, std::size_t slots) {
  if (smart) return std::make_unique<LiveStatus>(out, slots);
  return std::make_unique<PlainStatus>(out, slots);
}

bool IsSmartTerminal(int fd) {
  if (isatty(fd) == 0) return false;
  const char* term = std::getenv("TERM");
  return term != nullptr && std::string_view(term) != "dumb" && std::string_view(term) != "";
}

}  // namespace slamsweep::orchestrator::inline sweep
