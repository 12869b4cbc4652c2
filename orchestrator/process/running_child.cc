#include "orchestrator/process/running_child.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <string_view>

namespace slamsweep::orchestrator::inline process {
namespace {

// Enough for bubblewrap's one-line message when it cannot set a sandbox up.
constexpr std::size_t kOutputTailBytes = 512;

}  // namespace

ChildClock::time_point After(ChildClock::time_point now, double seconds) {
  seconds = std::clamp(seconds, 0.0, 1e9);
  return now + std::chrono::duration_cast<ChildClock::duration>(std::chrono::duration<double>(seconds));
}

void SignalGroup(pid_t group, int signal_number) { ::kill(-group, signal_number); }

void ReadChildOutput(RunningChild& child, std::size_t max_bytes) {
  std::array<char, 64 * 1024> buffer;
  std::size_t total = 0;
  while (child.output_fd >= 0 && total < max_bytes) {
    const ssize_t n = ::read(child.output_fd, buffer.data(), buffer.size());
    if (n > 0) {
      child.log.Append(std::string_view(buffer.data(), static_cast<std::size_t>(n)));
      if (child.sandboxed) {
        child.output_tail.append(buffer.data(), static_cast<std::size_t>(n));
        if (child.output_tail.size() > kOutputTailBytes) {
          child.output_tail.erase(0, child.output_tail.size() - kOutputTailBytes);
        }
      }
      total += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EAGAIN) return;
    // EOF (every writer closed it) or an error: the child may still run; only its exit is awaited now.
    ::close(child.output_fd);
    child.output_fd = -1;
  }
}

}  // namespace slamsweep::orchestrator::inline process
