#include "report/html/write_report.h"

#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "orchestrator/phase_times/phase_times.h"
#include "report/html/image_jobs.h"
#include "report/html/map_figures.h"
#include "report/html/metric_plot_plan.h"
#include "report/html/metric_spec_page.h"
#include "report/html/paper_files.h"
#include "report/html/report_layout.h"
#include "report/html/run_downloads.h"
#include "report/html/run_images.h"
#include "report/html/safe_name.h"
#include "report/html/site_data.h"
#include "report/html/site_files.h"
#include "report/html/trajectory_figures.h"
#include "report/html/validity_page.h"
#include "report/html/view_pages.h"
#include "report/model/load_runs.h"
#include "report/model/named_study.h"
#include "report/model/sweep_model.h"

namespace slamsweep::report::inline html {

namespace {

namespace fs = std::filesystem;

// Marks the plots whose files exist and counts the images made and not made. Without an image
// maker nothing counts as missing: the user asked for no images.
ReportSummary CountImages(const fs::path& out_dir, bool drawing, SiteData& site) {
  ReportSummary summary;
  for (auto& [sequence, artifacts] : site.plots) {
    for (PlotArtifact& plot : artifacts) {
      plot.made = IsRegularFileNoFollow(out_dir / plot.path);
      if (plot.made) plot.note.clear();
      if (plot.made) {
        ++summary.images;
      } else if (drawing) {
        ++summary.images_missing;
      }
    }
  }
  for (const RunArtifacts& artifacts : site.runs) {
    summary.images += static_cast<std::size_t>(artifacts.thumbnail) + artifacts.overlay + artifacts.gif;
    for (const std::string& note : artifacts.notes)
      summary.images_missing += note.find(" not made: ") != std::string::npos;
  }
  return summary;
}

}  // namespace

ReportSummary WriteReport(const fs::path& result_dir, const fs::path& out_dir, const ReportOptions& options) {
  std::optional<orchestrator::PhaseTimer> phase(std::in_place, "load");
  std::vector<RunRecord> records = LoadRuns(result_dir);
  phase.emplace("model");
  const SweepModel model = BuildSweepModel(std::move(records), LoadSweepModelOptions(result_dir));
  const ReportLayout layout(model);
  PrepareOutputDir(out_dir);

  SiteData site;
  site.model = &model;
  site.layout = &layout;
  site.significance = BuildSignificance(model);
  site.across_data_sets = BuildAcrossDataSets(model, site.significance);
  const AlgorithmPalette palette(model.algorithms);
  site.palette = &palette;
  fs::path normal = fs::absolute(result_dir).lexically_normal();
  if (normal.filename().empty()) normal = normal.parent_path();  // "out/" -> "out"
  site.title = model.sweep_name.empty() ? "slamsweep report — " + normal.filename().string() : model.sweep_name;
  site.runs.resize(model.runs.size());

  phase.emplace("downloads");
  ParallelFor(model.runs.size(), options.jobs, [&](std::size_t i) {
    const RunRecord& run = model.runs[i];
    const fs::path run_out = out_dir / layout.RunDir(i);
    MakeDirectories(run_out);
    CopyDownloads(run, run_out, site.runs[i]);
    LogTail tail = ReadLogTail(run.dir / "log.txt", options.log_tail_lines);
    site.runs[i].log_tail = std::move(tail.text);
    site.runs[i].log_truncated = tail.truncated;
  });

  phase.emplace("plan_images");
  std::vector<PlotRequest> plots = PlanPlots(model, layout, out_dir, site);
  std::vector<ScatterPlotJob> scatter_plots;
  ValiditySite validity = PlanValidity(model, *site.palette, out_dir, scatter_plots);
  std::vector<FigureJob> figures;
  PlanViewPages(out_dir, site, figures);
  PlanTrajectoryFigures(out_dir, site, figures);
  PlanRunPathErrorFigures(
      out_dir, site, figures,
      options.run_figures_for_every_run || model.runs.size() <= options.figures_for_every_run_up_to);
  std::vector<PlannedMapComparison> map_comparisons = PlanMapComparisons(out_dir, site);
  std::string figures_error;
  std::vector<ImageJob> jobs;
  if (options.artwork != nullptr) {
    if (!plots.empty()) {
      Artwork* artwork = options.artwork;
      jobs.push_back({[artwork, &plots] { artwork->Plots(plots); },
                      [&site](const std::string& error) {
                        // Made or not is decided below from the files; this keeps the reason.
                        for (auto& [sequence, artifacts] : site.plots) {
                          for (PlotArtifact& plot : artifacts)
                            plot.note = error.empty() ? "the plot file is missing" : error;
                        }
                      }});
    }
    if (!scatter_plots.empty()) {
      Artwork* artwork = options.artwork;
      jobs.push_back({[artwork, &scatter_plots] { artwork->ScatterPlots(scatter_plots); },
                      [&validity](const std::string& error) {
                        for (ValidityPlot& plot : validity.plots)
                          plot.note = error.empty() ? "the plot file is missing" : error;
                      }});
    }
    if (!figures.empty()) {
      Artwork* artwork = options.artwork;
      jobs.push_back({[artwork, &figures] { artwork->Figures(figures); },
                      [&figures_error](const std::string& error) { figures_error = error; }});
    }
    // One job per table: its panels share one window and scale, so they are drawn together.
    for (PlannedMapComparison& planned : map_comparisons) {
      Artwork* artwork = options.artwork;
      auto drawn = std::make_shared<MapComparisonDrawn>();
      jobs.push_back({[artwork, &planned, drawn] {
                        // Its own total in $SLAMSWEEP_PHASE_TIMES (inside "images"): what the maps cost the report.
                        const orchestrator::PhaseTimer timer("maps_compared");
                        *drawn = artwork->MapComparison(planned.job);
                      },
                      [&site, &planned, drawn](const std::string& error) {
                        MapsCompared& maps = site.maps_compared[planned.table_key];
                        maps.attempted = error.empty();
                        maps.error = error;
                        if (error.empty()) maps.drawn = *drawn;
                      }});
    }
    PlanRunImages(model, layout, out_dir, options, site, jobs);
  }
  PlanVectorMaps(model, layout, out_dir, options, site, jobs);
  phase.emplace("images");
  RunImageJobs(jobs, options.jobs);
  phase.emplace("pages");
  ReportSummary summary = CountImages(out_dir, options.artwork != nullptr, site);
  CountValidityPlots(out_dir, options.artwork != nullptr, validity, summary);
  const auto [figures_made, figures_missing] =
      MarkViewFigures(out_dir, options.artwork != nullptr, figures_error, site);
  summary.images += figures_made;
  summary.images_missing += figures_missing;
  const auto [run_figures_made, run_figures_missing] =
      MarkRunPathErrorFigures(out_dir, options.artwork != nullptr, figures_error, site);
  summary.images += run_figures_made;
  summary.images_missing += run_figures_missing;
  for (const auto& [table, maps] : site.maps_compared) {
    summary.images += maps.drawn.reference_made;
    for (const MapPanelDrawn& panel : maps.drawn.panels) {
      summary.images += static_cast<std::size_t>(panel.made) + panel.difference_made;
      summary.images_missing += static_cast<std::size_t>(!panel.made) + !panel.difference_note.empty();
    }
    if (!maps.attempted && options.artwork != nullptr) summary.images_missing += maps.panels.size();
  }

  // The sweep's own tables, as the orchestrator wrote them: one computation of every aggregate.
  site.has_summary_json = CopyResultFile(result_dir, out_dir, "summary.json");
  site.has_summary_csv = CopyResultFile(result_dir, out_dir, "summary.csv");
  site.has_runs_csv = CopyResultFile(result_dir, out_dir, "runs.csv");
  WriteTextFile(out_dir / "style.css",
                std::string(StyleSheet()) + ViewStyleSheet() + std::string(MapsComparedStyleSheet()));
  WritePaperFiles(model, layout, out_dir, site);
  if (options.history != nullptr) site.history_section = options.history->Write(out_dir, summary);
  validity.has_csv = CopyResultFile(result_dir, out_dir, "validity.csv");
  site.has_validity_page = !validity.study.empty();
  if (site.has_validity_page) {
    WriteTextFile(out_dir / "validity.html", RenderValidityPage(site, validity));
    ++summary.pages;
  } else {
    std::error_code ignored;
    fs::remove(out_dir / "validity.html", ignored);  // none left from an earlier report in this folder
  }
  WriteTextFile(out_dir / "metrics.html", RenderMetricSpecPage(site));
  WriteTextFile(out_dir / "index.html", RenderIndexPage(site));
  summary.pages += 2;
  for (const SequenceModel& sequence : model.sequences) {
    WriteTextFile(out_dir / layout.SequencePage(sequence.key), RenderSequencePage(site, sequence));
    ++summary.pages;
  }
  summary.pages += WriteViewPages(site, out_dir);
  ParallelFor(model.runs.size(), options.jobs,
              [&](std::size_t i) { WriteTextFile(out_dir / layout.RunPage(i), RenderRunPage(site, i)); });
  summary.pages += model.runs.size();
  summary.runs = model.runs.size();
  phase.reset();
  orchestrator::FlushPhaseTimes("report");
  return summary;
}

}  // namespace slamsweep::report::inline html
