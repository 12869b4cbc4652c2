#include "orchestrator/process/signal_wakeup.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <mutex>
#include <stdexcept>

namespace slamsweep::orchestrator::inline process {
namespace {

// Written by signal handlers, so a plain int set before any handler is installed.
int g_wakeup_fds[2] = {-1, -1};
std::once_flag g_pipe_once;
std::once_flag g_sigchld_once;

void OnChildSignal(int) { NotifySignalWakeup(); }

}  // namespace

int SignalWakeupFd() {
  std::call_once(g_pipe_once, [] {
    if (::pipe2(g_wakeup_fds, O_CLOEXEC | O_NONBLOCK) != 0) {
      throw std::runtime_error("cannot create the signal wake-up pipe");
    }
  });
  return g_wakeup_fds[0];
}

void NotifySignalWakeup() {
  const int saved_errno = errno;  // a handler must not disturb the interrupted code's errno
  if (g_wakeup_fds[1] >= 0) {
    const char byte = 1;
    [[maybe_unused]] const ssize_t ignored = ::write(g_wakeup_fds[1], &byte, 1);
  }
  errno = saved_errno;
}

void DrainSignalWakeup() {
  std::array<char, 256> buffer;
  while (::read(SignalWakeupFd(), buffer.data(), buffer.size()) > 0) {
  }
}

void EnsureChildSignalHandler() {
  SignalWakeupFd();
  std::call_once(g_sigchld_once, [] {
    struct sigaction action = {};
    action.sa_handler = OnChildSignal;
    sigemptyset(&action.sa_mask);
    // SA_RESTART: other code's blocking calls must not start failing with EINTR because a child ended.
    action.sa_flags = SA_RESTART | SA_NOCLDSTOP;
    ::sigaction(SIGCHLD, &action, nullptr);
  });
}

}  // namespace slamsweep::orchestrator::inline process
