#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "report/html/artwork.h"
#include "report/html/site_extension.h"

namespace slamsweep::report::inline html {

/// How `slamsweep report` builds the site.
struct ReportOptions {
  /// Draws plots, thumbnails, overlays and GIFs; null leaves every image out (pages say so).
  Artwork* artwork = nullptr;
  /// Threads making images at once (the machine's cores by default in the CLI).
  int jobs = 2;
  int thumbnail_px = 320;
  int overlay_px = 480;
  GifSettings gif;
  /// A run's own figures (trajectory over the map, thumbnail, GIF from separate stage images) are drawn for
  /// every run of a sweep of at most this many runs; above it only for the runs the galleries show (each
  /// row's median run) and failed runs, unless run_figures_for_every_run (`--run-figures all`).
  std::size_t figures_for_every_run_up_to = 500;
  bool run_figures_for_every_run = false;
  /// Lines of log.txt shown on a run page (the whole log is downloadable).
  std::size_t log_tail_lines = 60;
  /// Nightly history pages and the comparison with the previous night (report/history); null: none.
  SiteExtension* history = nullptr;
};

/// What WriteReport did, for the command's message.
struct ReportSummary {
  std::size_t runs = 0;
  std::size_t pages = 0;
  std::size_t images = 0;
  std::size_t images_missing = 0;  ///< images that could not be made (each named on its page)
};

/// Turns a sweep's output directory (orchestrator/DESIGN.md) into a static site in `out_dir`:
/// index.html, sequences/*.html, runs/*.html (+ runs/<name>/ images and downloads), plots/,
/// files/<algorithm>/<sequence>/ text files, summary.csv, summary.json (copied), style.css.
/// Pages use no script, no inline style and no data: URI, so they work from file:// and under
/// Jenkins' default Content-Security-Policy. A run that failed or whose files are broken is shown
/// as such; only an unusable `result_dir` or an unwritable `out_dir` is an error
/// (evaluator::InputError naming the path).
ReportSummary WriteReport(const std::filesystem::path& result_dir, const std::filesystem::path& out_dir,
                          const ReportOptions& options);

}  // namespace slamsweep::report::inline html
