#pragma once

#include <filesystem>
#include <memory>

#include "orchestrator/history/regression.h"
#include "report/html/write_report.h"

namespace slamsweep::report::inline history {

/// What `slamsweep report RESULT_DIR --history FILE [--compare-previous]` adds to the site.
struct HistorySiteOptions {
  /// The history database (orchestrator/history); must exist.
  std::filesystem::path history_file;
  /// The sweep the report is about; shown as the last night when it is not recorded yet.
  std::filesystem::path result_dir;
  /// Adds the regressions and improvements against the night before this sweep to the index.
  bool compare_previous = false;
  orchestrator::RegressionOptions regression;
  /// False: pages only (tests, --no-images).
  bool draw_plots = true;
  std::filesystem::path gnuplot = "/usr/bin/gnuplot";
};

/// The nightly-history part of the site, for ReportOptions::history: out_dir/history/<series>.html (+ .png) per
/// algorithm x sequence x noise x metric (rmse for trajectory metrics, value for map metrics) and a section in the
/// index. A plot that cannot be drawn is a note on its page, not an error; a missing or foreign history file is
/// an InputError naming it.
std::unique_ptr<SiteExtension> MakeHistorySite(const HistorySiteOptions& options);

}  // namespace slamsweep::report::inline history
