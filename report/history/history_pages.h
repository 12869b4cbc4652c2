#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/history/history_store.h"
#include "orchestrator/history/regression.h"
#include "report/html/html.h"

namespace slamsweep::report::inline history {

/// One night of a series as its history page shows it.
struct NightPoint {
  std::string label;
  std::string started_at;
  std::size_t n = 0;
  double mean = 0.0;
  double min = 0.0;
  double max = 0.0;
  std::optional<double> std;
  std::int64_t failed_runs = 0;
  /// That night's report, relative to the page showing the link; empty when it cannot be reached (text only).
  std::string report_href;
  /// The sweep this report is about.
  bool current = false;
};

/// One algorithm x sequence x noise x odometry mode x metric across nights.
struct HistorySeriesPage {
  orchestrator::SeriesKey key;
  /// Relative to the report root: "history/<safe name>.html".
  std::string page;
  /// Relative to the report root: "history/<safe name>.png"; drawn or not per `plot_made`.
  std::string plot;
  bool plot_made = false;
  /// Why the plot is missing.
  std::string plot_note;
  /// In recorded order; nights without a sample of the series are left out.
  std::vector<NightPoint> nights;
};

/// A night in the index's list of nights.
struct NightLink {
  std::string label;
  std::string started_at;
  /// Relative to the report root; empty when that night's report cannot be reached.
  std::string report_href;
  bool current = false;
};

/// What the index's history section shows.
struct HistorySection {
  std::filesystem::path history_file;
  std::vector<NightLink> nights;
  std::vector<HistorySeriesPage> pages;
  /// With --compare-previous: the comparison of this sweep with the night before it.
  std::optional<orchestrator::Comparison> comparison;
  /// Why there is no comparison although one was asked for (e.g. no earlier night).
  std::string comparison_note;
};

/// "history/<algorithm>-<sequence>-<noise>-<odometry>-<metric>" made safe as a file name (SafeFileName), without
/// extension.
std::string HistoryPageStem(const orchestrator::SeriesKey& key);

/// The summary of one night's samples (mean, min, max, sample standard deviation when n >= 2).
NightPoint SummarizeNight(const std::vector<double>& values);

/// A history page (history/<stem>.html): the plot, then a table of nights with links to their reports.
/// No script, no inline style, every value escaped.
std::string RenderHistoryPage(const HistorySeriesPage& page);

/// The index's "Nightly history" section: nights with links, regressions and improvements, links to every page.
Html RenderHistorySection(const HistorySection& section);

/// The gnuplot script drawing `page` to `png`: x = night, y = mean with a min-max band, log y when every value is
/// positive (like the report's other plots).
std::string HistoryPlotScript(const HistorySeriesPage& page, const std::filesystem::path& png);

}  // namespace slamsweep::report::inline history
