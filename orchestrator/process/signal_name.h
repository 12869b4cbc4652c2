#pragma once

#include <string>

namespace slamsweep::orchestrator::inline process {

/// "SIGSEGV" for 11 and so on; "signal N" for numbers without a standard name.
std::string SignalName(int signal_number);

}  // namespace slamsweep::orchestrator::inline process
