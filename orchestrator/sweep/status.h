#pragma once

#include <chrono>
#include <cstddef>
#include <iosfwd>
#include <memory>
#include <string>

namespace slamsweep::orchestrator::inline sweep {

/// What the sweep loop tells the person or the CI log watching it (ninja's Status).
struct FinishedRun {
  std::string run_id;
  bool ok = false;
  /// Failure kind and reason for failed runs ("timeout: timed out after 120 s").
  std::string reason;
  double wall_s = 0.0;
};

class Status {
 public:
  virtual ~Status() = default;
  /// `to_run` runs will be started; `already_done` were finished by an earlier sweep.
  virtual void Planned(std::size_t to_run, std::size_t already_done) = 0;
  virtual void Started(const std::string& run_id) = 0;
  virtual void Finished(const FinishedRun& run) = 0;
  /// A line that must be seen (budget exhausted, interruption); never overwritten.
  virtual void Message(const std::string& text) = 0;
  /// The sweep is over; clears a live line.
  virtual void Done() = 0;
};

/// Remaining time at the throughput seen so far (elapsed time per finished run, which already
/// includes the parallelism achieved, times the runs not finished). Empty before the first run
/// ends and after the last.
std::string EstimateRemaining(std::size_t finished, std::size_t total, std::size_t slots,
                              std::chrono::steady_clock::duration elapsed);

/// One redrawn line on a terminal ("[12/36] 2 running, 1 failed, ETA 1m20s  icp-slam-..."),
/// failures printed above it; plain timestamped lines otherwise (Jenkins console), one per finished
/// run. `smart` decides which: pass IsSmartTerminal(stdout).
std::unique_ptr<Status> MakeStatus(std::ostream& out, bool smart, std::size_t slots);

/// A terminal that can redraw a line: a tty whose TERM is set and not "dumb".
bool IsSmartTerminal(int fd);

}  // namespace slamsweep::orchestrator::inline sweep
