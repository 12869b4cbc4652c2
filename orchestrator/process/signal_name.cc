#include "orchestrator/process/signal_name.h"

#include <csignal>
#include <cstring>

namespace slamsweep::orchestrator::inline process {

std::string SignalName(int signal_number) {
  // glibc >= 2.32 knows the abbreviations; real-time signals get none and are rare enough for a number.
  if (signal_number > 0 && signal_number < NSIG) {
    if (const char* abbreviation = sigabbrev_np(signal_number)) return std::string("SIG") + abbreviation;
  }
  return "signal " + std::to_string(signal_number);
}

}  // namespace slamsweep::orchestrator::inline process
