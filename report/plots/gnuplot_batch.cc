#include "report/plots/gnuplot_batch.h"

#include <fmt/format.h>

#include <regex>
#include <stdexcept>
#include <system_error>

#include "report/plots/gnuplot_process.h"
#include "report/plots/metric_plot_script.h"
#include "report/plots/png_repack.h"

namespace slamsweep::report::inline plots {
namespace {

constexpr std::string_view kDoneMarker = "SLAMSWEEP_PLOTS_DONE";

/// The part of gnuplot's stderr printed while job `index` ran (between its marker and the next).
std::string SectionOf(const std::string& text, std::size_t index, std::size_t job_count) {
  const std::string start_marker = PlotMarker(index);
  const std::size_t start = text.find(start_marker + "\n");
  if (start == std::string::npos) return {};
  const std::size_t body = start + start_marker.size() + 1;
  const std::string next_marker = index + 1 < job_count ? PlotMarker(index + 1) : std::string(kDoneMarker);
  const std::size_t end = text.find(next_marker + "\n", body);
  return text.substr(body, end == std::string::npos ? std::string::npos : end - body);
}

/// Gnuplot reports an error as "line N: message" and a warning as "line N: warning: message".
bool HasError(const std::string& section) {
  static const std::regex kError(R"(line \d+: (?!warning:))");
  return std::regex_search(section, kError);
}

bool NonEmptyFile(const std::filesystem::path& path) {
  std::error_code error;
  const auto size = std::filesystem::file_size(path, error);
  return !error && size > 0;
}

std::string Trimmed(std::string text) {
  constexpr std::size_t kMaxChars = 2000;
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  if (text.size() > kMaxChars) text = "..." + text.substr(text.size() - kMaxChars);
  return text;
}

}  // namespace

void RunGnuplotBatch(const std::vector<GnuplotBatchJob>& jobs) {
  if (jobs.empty()) return;
  std::string script;
  for (const GnuplotBatchJob& job : jobs) {
    // A stale PNG from an earlier report must not pass for this one if gnuplot fails.
    std::error_code ignored;
    std::filesystem::remove(job.png, ignored);
    script += job.script;
  }
  script += fmt::format("print '{}'\n", kDoneMarker);

  const GnuplotOutcome outcome = RunGnuplot(script);
  const bool finished = outcome.stderr_text.find(std::string(kDoneMarker) + "\n") != std::string::npos;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const std::string section = SectionOf(outcome.stderr_text, i, jobs.size());
    if (HasError(section) || !NonEmptyFile(jobs[i].png)) {
      throw std::runtime_error(fmt::format("gnuplot could not draw the plot '{}' ({}), exit code {}: {}", jobs[i].title,
                                           jobs[i].png.string(), outcome.exit_code,
                                           Trimmed(section.empty() ? outcome.stderr_text : section)));
    }
  }
  if (!finished || outcome.exit_code != 0) {
    throw std::runtime_error(fmt::format("gnuplot ended with exit code {} while drawing {} plots: {}",
                                         outcome.exit_code, jobs.size(), Trimmed(outcome.stderr_text)));
  }
  // pngcairo writes RGB; a plot has few colours, so a palette PNG holds the same pixels in far fewer bytes.
  for (const GnuplotBatchJob& job : jobs) RepackAsPalettePng(job.png);
}

}  // namespace slamsweep::report::inline plots
