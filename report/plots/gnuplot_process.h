#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace slamsweep::report::inline plots {

/// What a gnuplot process left behind.
struct GnuplotOutcome {
  /// The process's exit status, or 128 + signal number when a signal ended it.
  int exit_code = 0;
  /// Everything gnuplot wrote on stderr: its error messages and the `print` output of the script.
  std::string stderr_text;
};

/// Runs `gnuplot -d` (no init files, so a user's ~/.gnuplot cannot change the plots) as a child
/// process (orchestrator::RunToExit: no shell, no timeout) with `script` as its standard input and
/// stdout discarded; waits for it to end.
/// The script and stderr go through unlinked temporary files rather than pipes: no deadlock when
/// gnuplot writes much to stderr, and no SIGPIPE in this process when gnuplot stops early.
/// Throws std::runtime_error when the program cannot be started (naming it) or a temporary file
/// cannot be made. A script error is not an exception here: it shows in the outcome.
GnuplotOutcome RunGnuplot(std::string_view script, const std::filesystem::path& program = "/usr/bin/gnuplot");

}  // namespace slamsweep::report::inline plots
