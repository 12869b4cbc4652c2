#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace slamsweep::report {

/// One PNG of a batch: the gnuplot commands that draw it, which must begin with
/// `print PlotMarker(index)` (after `reset`) and end with `unset output`.
struct GnuplotBatchJob {
  std::string script;
  std::filesystem::path png;
  std::string title;  ///< for error messages
};

/// Runs every job's script in ONE gnuplot process (starting gnuplot costs far more than a plot),
/// after removing stale PNGs. Throws std::runtime_error naming the first job whose section of
/// gnuplot's stderr holds an error or whose PNG is missing, quoting that section, or when gnuplot
/// does not finish. Does nothing for no jobs.
void RunGnuplotBatch(const std::vector<GnuplotBatchJob>& jobs);

}  // namespace slamsweep::report
