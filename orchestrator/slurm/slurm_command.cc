#include "orchestrator/slurm/slurm_command.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>

#include "orchestrator/process/spawn.h"

namespace slamsweep::orchestrator::inline slurm {
namespace {

constexpr std::size_t kMaxOutputBytes = 4 << 20;

}  // namespace

CommandOutput RunSlurmCommand(const std::vector<std::string>& argv, double timeout_s) {
  CommandOutput result;
  ProcessSpec spec;
  spec.argv = argv;
  const SpawnResult child = SpawnChild(spec);
  if (child.pid < 0) {
    result.output = "cannot start '" + (argv.empty() ? std::string() : argv.front()) + "': " + child.error;
    return result;
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  bool timed_out = false;
  char buffer[8192];
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd fd = {child.output_fd, POLLIN, 0};
    const int ready = ::poll(&fd, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    const ssize_t got = ::read(child.output_fd, buffer, sizeof buffer);
    if (got == 0) break;  // every writer closed: the command is done (or daemonised its output away)
    if (got < 0) {
      if (errno == EAGAIN || errno == EINTR) continue;
      break;
    }
    if (result.output.size() < kMaxOutputBytes) result.output.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(child.output_fd);
  if (timed_out) ::kill(-child.pid, SIGKILL);
  int status = 0;
  while (::waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (timed_out) {
    result.output += "\n(killed after " + std::to_string(static_cast<int>(timeout_s)) + " s)";
    return result;
  }
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace slamsweep::orchestrator::inline slurm
