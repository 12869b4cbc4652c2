#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace slamsweep::report::inline plots {

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

/// RunGnuplotBatch of one GnuplotBatchJob per plot job: `to_batch_job(jobs[i], i)`, where i is the
/// index its script's PlotMarker must use.
template <typename Job, typename ToBatchJob>
void RunGnuplotJobs(const std::vector<Job>& jobs, ToBatchJob to_batch_job) {
  std::vector<GnuplotBatchJob> batch;
  batch.reserve(jobs.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) batch.push_back(to_batch_job(jobs[i], i));
  RunGnuplotBatch(batch);
}

}  // namespace slamsweep::report::inline plots
