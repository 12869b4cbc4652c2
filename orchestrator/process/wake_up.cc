#include "orchestrator/process/wake_up.h"

#include <poll.h>
#include <pthread.h>
#include <signal.h>

#include <algorithm>
#include <atomic>

#include "orchestrator/process/signal_wakeup.h"

namespace slamsweep::orchestrator::inline process {
namespace {

std::atomic<bool> g_wake_up_requested = false;
static_assert(std::atomic<bool>::is_always_lock_free, "RequestWakeUp must stay async-signal-safe");

}  // namespace

void RequestWakeUp() {
  g_wake_up_requested.store(true);
  NotifySignalWakeup();
}

bool TakeWakeUpRequest() { return g_wake_up_requested.exchange(false); }

void SleepUnlessWoken(double seconds) {
  if (g_wake_up_requested.load()) return;
  sigset_t open_mask;
  pthread_sigmask(SIG_SETMASK, nullptr, &open_mask);
  // Not SIGCHLD: children are ProcessSet's business, and a SIGCHLD taken here (one of another thread's
  // short commands, say) would wake this sleep for nothing.
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) sigdelset(&open_mask, signal_number);
  const auto ns = static_cast<long long>(std::clamp(seconds, 0.0, 1e6) * 1e9);
  timespec timeout = {static_cast<time_t>(ns / 1000000000), static_cast<long>(ns % 1000000000)};
  pollfd wake = {SignalWakeupFd(), POLLIN, 0};
  if (::ppoll(&wake, 1, &timeout, &open_mask) > 0) DrainSignalWakeup();
}

}  // namespace slamsweep::orchestrator::inline process
