#include "orchestrator/process/interruption.h"

#include <pthread.h>

#include <array>
#include <atomic>
#include <csignal>
#include <mutex>

#include "orchestrator/process/signal_wakeup.h"

namespace slamsweep::orchestrator::inline process {
namespace {

constexpr std::array<int, 3> kInterruptSignals = {SIGINT, SIGTERM, SIGHUP};

volatile std::sig_atomic_t g_interrupt_signal = 0;
std::mutex g_mutex;
std::atomic<int> g_depth = 0;
std::array<struct sigaction, kInterruptSignals.size()> g_previous_actions;

void OnInterrupt(int signal_number) {
  g_interrupt_signal = signal_number;
  NotifySignalWakeup();
}

sigset_t InterruptSet() {
  sigset_t set;
  sigemptyset(&set);
  for (const int signal_number : kInterruptSignals) sigaddset(&set, signal_number);
  return set;
}

}  // namespace

InterruptionGuard::InterruptionGuard() {
  SignalWakeupFd();  // the pipe must exist before a handler can write to it
  {
    const std::lock_guard lock(g_mutex);
    if (g_depth++ == 0) {
      g_interrupt_signal = 0;
      struct sigaction action = {};
      action.sa_handler = OnInterrupt;
      sigemptyset(&action.sa_mask);
      action.sa_flags = SA_RESTART;
      for (std::size_t i = 0; i < kInterruptSignals.size(); ++i) {
        ::sigaction(kInterruptSignals[i], &action, &g_previous_actions[i]);
      }
    }
  }
  const sigset_t set = InterruptSet();
  pthread_sigmask(SIG_BLOCK, &set, &previous_mask_);
}

InterruptionGuard::~InterruptionGuard() {
  // Unblock first: a signal still pending then reaches our handler and is recorded, not lost.
  pthread_sigmask(SIG_SETMASK, &previous_mask_, nullptr);
  const std::lock_guard lock(g_mutex);
  if (--g_depth == 0) {
    for (std::size_t i = 0; i < kInterruptSignals.size(); ++i) {
      ::sigaction(kInterruptSignals[i], &g_previous_actions[i], nullptr);
    }
  }
}

bool InterruptionGuard::Interrupted() { return g_interrupt_signal != 0; }

int InterruptionGuard::Signal() { return g_interrupt_signal; }

bool InterruptionPending() { return g_depth.load() > 0 && g_interrupt_signal != 0; }

}  // namespace slamsweep::orchestrator::inline process
