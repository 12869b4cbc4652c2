#include "orchestrator/process/outcome_reason.h"

#include <fmt/format.h>

#include "orchestrator/process/signal_name.h"

namespace slamsweep::orchestrator::inline process {

std::string ExitReason(int exit_code) { return fmt::format("exit code {}", exit_code); }

std::string SignalReason(int signal_number) {
  return fmt::format("killed by {} (signal {})", SignalName(signal_number), signal_number);
}

std::string StopReason(bool needed_kill, double grace_s) {
  if (!needed_kill) return "SIGTERM";
  return fmt::format("SIGTERM, then SIGKILL after {:g} s grace", grace_s);
}

std::string TimeoutReason(double timeout_s, bool needed_kill, double grace_s) {
  return fmt::format("timed out after {:.1f} s ({})", timeout_s, StopReason(needed_kill, grace_s));
}

std::string MemoryReason(std::int64_t group_rss_kb, std::uint64_t limit_mb) {
  const double rss_mb = static_cast<double>(group_rss_kb) / 1024.0;
  if (rss_mb >= 1024.0) {
    return fmt::format("peak memory {:.1f} GB above the {} MB limit", rss_mb / 1024.0, limit_mb);
  }
  return fmt::format("peak memory {:.0f} MB above the {} MB limit", rss_mb, limit_mb);
}

std::string ProcessLimitReason(std::uint64_t limit) {
  return fmt::format("reached the process limit: {} processes and threads at once (process_limit)", limit);
}

std::string SandboxFailureReason(int exit_code, const std::string& message) {
  if (message.empty()) return fmt::format("the sandbox could not be set up (bwrap exited with {})", exit_code);
  return fmt::format("the sandbox could not be set up (bwrap exited with {}: {})", exit_code, message);
}

std::string InterruptReason(int interrupt_signal, bool needed_kill, double grace_s) {
  if (interrupt_signal == 0) return fmt::format("stopped by the supervisor ({})", StopReason(needed_kill, grace_s));
  return fmt::format("interrupted by {} ({})", SignalName(interrupt_signal), StopReason(needed_kill, grace_s));
}

std::string StartFailureReason(const std::string& program, const std::string& detail) {
  return fmt::format("cannot start '{}': {}", program, detail);
}

}  // namespace slamsweep::orchestrator::inline process
