// `slamsweep report RESULT_DIR [-o DIR]`: a sweep's output directory as a static HTML site.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>

#include "cli/command.h"
#include "report/history/history_site.h"
#include "report/html/standard_artwork.h"
#include "report/html/write_report.h"

namespace slamsweep::cli {

void RegisterReportCommand(CLI::App& app, const Streams& streams) {
  struct Options {
    std::string result_dir;
    std::string output_dir;
    int jobs = 0;
    int thumbnail_px = 320;
    int gif_max_side_px = 480;
    std::size_t log_lines = 60;
    bool no_images = false;
    std::string history;
    bool compare_previous = false;
    std::string run_figures = "auto";
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand("report", "turn a sweep's output directory into a static HTML report");
  command->add_option("RESULT_DIR", options->result_dir, "the sweep's output directory (summary.json, runs/)")
      ->required();
  command->add_option("-o,--output", options->output_dir, "report folder (default: RESULT_DIR/report)");
  command->add_option("-j,--jobs", options->jobs, "images made at once (default: the cores)")
      ->check(CLI::NonNegativeNumber);
  command->add_option("--thumbnail-px", options->thumbnail_px, "longer side of gallery thumbnails, pixels")
      ->capture_default_str()
      ->check(CLI::Range(16, 4096));
  command->add_option("--gif-max-side-px", options->gif_max_side_px, "longer side of map-building GIFs, pixels")
      ->capture_default_str()
      ->check(CLI::Range(16, 4096));
  command->add_option("--log-lines", options->log_lines, "lines of each run's log shown on its page")
      ->capture_default_str();
  command->add_flag("--no-images", options->no_images, "pages and files only: no plots, thumbnails or GIFs");
  command
      ->add_option("--run-figures", options->run_figures,
                   "each run's own figures (trajectory over the map, thumbnail): auto = every run's up to 500 "
                   "runs, beyond that each table row's median run and failed runs; all = every run's")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "all"}));
  command->add_option("--history", options->history,
                      "nightly history database (slamsweep history record): adds a history page per metric");
  command
      ->add_flag("--compare-previous", options->compare_previous,
                 "with --history: list regressions and improvements against the night before")
      ->needs("--history");
  command->callback([options, streams] {
    const std::filesystem::path result_dir = options->result_dir;
    const std::filesystem::path out_dir =
        options->output_dir.empty() ? result_dir / "report" : std::filesystem::path(options->output_dir);
    std::unique_ptr<report::Artwork> artwork = options->no_images ? nullptr : report::MakeStandardArtwork();
    report::ReportOptions report_options;
    report_options.artwork = artwork.get();
    report_options.jobs =
        options->jobs > 0 ? options->jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    report_options.thumbnail_px = options->thumbnail_px;
    report_options.gif.max_side_px = options->gif_max_side_px;
    report_options.log_tail_lines = options->log_lines;
    report_options.run_figures_for_every_run = options->run_figures == "all";
    std::unique_ptr<report::SiteExtension> history;
    if (!options->history.empty()) {
      report::HistorySiteOptions history_options;
      history_options.history_file = options->history;
      history_options.result_dir = result_dir;
      history_options.compare_previous = options->compare_previous;
      history_options.draw_plots = !options->no_images;
      history = report::MakeHistorySite(history_options);
      report_options.history = history.get();
    }
    const report::ReportSummary summary = report::WriteReport(result_dir, out_dir, report_options);
    streams.out << "report: " << (out_dir / "index.html").string() << " (" << summary.runs << " runs, " << summary.pages
                << " pages, " << summary.images << " images";
    if (summary.images_missing > 0)
      streams.out << ", " << summary.images_missing << " images not made: see their pages";
    if (!options->no_images && !report::StandardArtworkDrawsImages()) {
      streams.out << "; this build draws no images";
    }
    streams.out << ")\n";
  });
}

}  // namespace slamsweep::cli
