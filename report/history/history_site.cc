#include "report/history/history_site.h"

#include <algorithm>
#include <fstream>
#include <optional>
#include <system_error>

#include "evaluator/core/input_error.h"
#include "orchestrator/history/history_store.h"
#include "orchestrator/history/night.h"
#include "report/history/history_pages.h"
#include "report/plots/gnuplot_process.h"

namespace slamsweep::report::inline history {
namespace {

namespace fs = std::filesystem;
using orchestrator::HistoryStore;
using orchestrator::Night;
using orchestrator::NightEntry;

void WriteText(const fs::path& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << content;
  out.close();
  if (!out) throw evaluator::InputError(path.string() + ": cannot write");
}

bool IsRegularFile(const fs::path& path) {
  std::error_code error;
  return fs::is_regular_file(path, error);
}

// A link from `from_dir` to another night's report: relative, and only when the file is there (the site's link
// checker requires every href to resolve; a night whose output directory is gone is named without a link).
std::string ReportHref(const fs::path& report_index, const fs::path& from_dir) {
  if (report_index.empty() || !IsRegularFile(report_index)) return "";
  std::error_code error;
  const fs::path relative = fs::relative(report_index, from_dir, error);
  if (error || relative.empty()) return "";
  return relative.generic_string();
}

bool SameNight(const NightEntry& entry, const std::optional<Night>& current) {
  return current && entry.result_dir == current->result_dir && entry.sweep_id == current->sweep_id;
}

class HistorySite final : public SiteExtension {
 public:
  explicit HistorySite(HistorySiteOptions options) : options_(std::move(options)) {}

  Html Write(const fs::path& out_dir, ReportSummary& summary) override {
    const HistoryStore store = HistoryStore::OpenExisting(options_.history_file);
    std::optional<Night> current;
    std::string current_problem;
    try {
      current = orchestrator::ReadNight(options_.result_dir, "");
    } catch (const evaluator::InputError& error) {
      current_problem = error.what();
    }
    const std::vector<NightEntry> nights = store.Nights();
    bool current_recorded = false;
    for (const NightEntry& night : nights) current_recorded = current_recorded || SameNight(night, current);

    const fs::path history_dir = out_dir / "history";
    std::error_code error;
    fs::remove_all(history_dir, error);
    fs::create_directories(history_dir, error);
    if (error) throw evaluator::InputError(history_dir.string() + ": cannot create folder (" + error.message() + ")");

    HistorySection section;
    section.history_file = options_.history_file;
    for (const NightEntry& night : nights) {
      const bool is_current = SameNight(night, current);
      section.nights.push_back({night.label, night.started_at,
                                is_current ? "index.html" : ReportHref(night.report_index, out_dir), is_current});
    }
    if (current && !current_recorded) {
      section.nights.push_back({current->label + " (not recorded)", current->started_at, "index.html", true});
    }

    std::vector<orchestrator::SeriesKey> keys = store.SeriesKeys();
    if (current && !current_recorded) {
      for (const orchestrator::SampleSeries& s : current->series) {
        const bool known = std::any_of(
            keys.begin(), keys.end(), [&](const orchestrator::SeriesKey& k) { return orchestrator::SameSeries(k, s); });
        if (!known) keys.push_back(s);
      }
    }
    for (const orchestrator::SeriesKey& key : keys) {
      // One page per metric: the statistic the regression test compares (rmse, or value for map metrics).
      if (key.statistic != "rmse" && key.statistic != "value") continue;
      HistorySeriesPage page;
      page.key = key;
      const std::string stem = HistoryPageStem(key);
      page.page = stem + ".html";
      page.plot = stem + ".png";
      for (const orchestrator::HistoryPoint& point : store.Series(key)) {
        NightPoint night = SummarizeNight(point.values);
        night.label = point.night.label;
        night.started_at = point.night.started_at;
        night.failed_runs = point.failed_runs;
        night.current = SameNight(point.night, current);
        night.report_href = night.current ? "../index.html" : ReportHref(point.night.report_index, history_dir);
        page.nights.push_back(std::move(night));
      }
      if (current && !current_recorded) {
        if (const auto* s = orchestrator::FindSeries(*current, key)) {
          NightPoint night = SummarizeNight(s->values);
          night.label = current->label + " (not recorded)";
          night.started_at = current->started_at;
          night.current = true;
          night.report_href = "../index.html";
          for (const auto& cell : current->cells) {
            if (cell.algorithm == key.algorithm && cell.sequence == key.sequence && cell.noise == key.noise &&
                cell.odometry == key.odometry) {
              night.failed_runs = cell.failed_runs;
            }
          }
          page.nights.push_back(std::move(night));
        }
      }
      DrawPlot(out_dir, page, summary);
      WriteText(out_dir / page.page, RenderHistoryPage(page));
      ++summary.pages;
      section.pages.push_back(std::move(page));
    }

    if (options_.compare_previous) {
      if (!current) {
        section.comparison_note = "No comparison with the previous night: " + current_problem;
      } else if (const auto previous = orchestrator::PreviousNight(store, *current)) {
        section.comparison = orchestrator::CompareNights(store.Load(previous->id), *current, options_.regression);
      } else {
        section.comparison_note = "No comparison: the history holds no night before this sweep.";
      }
    }
    return RenderHistorySection(section);
  }

 private:
  void DrawPlot(const fs::path& out_dir, HistorySeriesPage& page, ReportSummary& summary) const {
    if (!options_.draw_plots) {
      page.plot_note = "images were not requested";
      return;
    }
    const fs::path png = out_dir / page.plot;
    try {
      const GnuplotOutcome outcome = RunGnuplot(HistoryPlotScript(page, png), options_.gnuplot);
      page.plot_made = outcome.exit_code == 0 && IsRegularFile(png);
      if (!page.plot_made) page.plot_note = "gnuplot failed: " + outcome.stderr_text.substr(0, 300);
    } catch (const std::exception& error) {
      page.plot_note = error.what();
    }
    if (page.plot_made) {
      ++summary.images;
    } else {
      ++summary.images_missing;
    }
  }

  HistorySiteOptions options_;
};

}  // namespace

std::unique_ptr<SiteExtension> MakeHistorySite(const HistorySiteOptions& options) {
  orchestrator::ValidateRegressionOptions(options.regression, "--");
  return std::make_unique<HistorySite>(options);
}

}  // namespace slamsweep::report::inline history
