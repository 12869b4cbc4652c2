#include "report/html/write_report.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <fstream>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <system_error>
#include <thread>

#include "evaluator/core/input_error.h"
#include "orchestrator/phase_times/phase_times.h"
#include "report/html/map_figures.h"
#include "report/html/metric_spec_page.h"
#include "report/html/report_layout.h"
#include "report/html/site_data.h"
#include "report/html/trajectory_figures.h"
#include "report/html/text_outputs.h"
#include "report/html/validity_page.h"
#include "report/html/vector_map_download.h"
#include "report/html/view_pages.h"
#include "report/model/load_runs.h"
#include "report/model/named_study.h"
#include "report/model/sweep_model.h"
#include "report/html/safe_name.h"

namespace slamsweep::report {

namespace {

namespace fs = std::filesystem;
using evaluator::InputError;

// Marks a folder as made by this command, so that a re-run may clear it and a typo in -o
// (say, the home folder) is refused instead of filled with report files.
constexpr const char* kMarker = ".slamsweep-report";

// Files of a run folder (orchestrator/DESIGN.md) offered for download, in display order. Fixed
// names only: paths named inside result.json are not trusted to stay inside the run folder.
constexpr const char* kDownloads[] = {"map.png",       "map.pgm",     "map.yaml",    "trajectory.tum",
                                      "reference.tum", "map.geojson", "stages.png",  "log.txt",
                                      "command.txt",   "run.json",    "result.json", "rpe_segments.csv"};

void WriteTextFile(const fs::path& path, std::string_view content) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  out.close();
  if (!out) throw InputError(path.string() + ": cannot write");
}

void MakeDirectories(const fs::path& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) throw InputError(dir.string() + ": cannot create folder (" + error.message() + ")");
}

void PrepareOutputDir(const fs::path& out_dir) {
  std::error_code error;
  if (fs::exists(out_dir, error)) {
    if (!fs::is_directory(out_dir, error)) throw InputError(out_dir.string() + ": exists and is not a folder");
    const bool empty = fs::directory_iterator(out_dir, error) == fs::directory_iterator();
    if (!empty && !fs::exists(out_dir / kMarker, error)) {
      throw InputError(out_dir.string() + ": not empty and not a slamsweep report; choose another -o folder");
    }
    for (const char* part : {"runs", "sequences", "plots", "files"}) fs::remove_all(out_dir / part, error);
  }
  for (const char* part : {"", "runs", "sequences", "plots", "files"}) MakeDirectories(out_dir / part);
  WriteTextFile(out_dir / kMarker, "made by slamsweep report\n");
}

bool IsSafeRelative(const std::string& text) {
  const fs::path path(text);
  if (text.empty() || path.is_absolute()) return false;
  for (const fs::path& part : path) {
    if (part == "..") return false;
  }
  return true;
}

// The final map's image: map.png since the worker writes PNG maps, map.pgm in older run folders.
fs::path MapImage(const RunRecord& run) {
  return IsRegularFileNoFollow(run.dir / "map.png") ? run.dir / "map.png" : run.dir / "map.pgm";
}

// The run's stage animation (one animated PNG of every stage), when its folder has one.
std::optional<fs::path> StageAnimation(const RunRecord& run) {
  const std::string& name = run.outputs.stage_animation;
  if (name.empty() || !IsSafeRelative(name) || !IsRegularFileNoFollow(run.dir / name)) return std::nullopt;
  return run.dir / name;
}

std::vector<fs::path> StagePaths(const RunRecord& run) {
  std::vector<fs::path> stages;
  for (const std::string& stage : run.outputs.stages) {
    if (IsSafeRelative(stage) && IsRegularFileNoFollow(run.dir / stage)) stages.push_back(run.dir / stage);
  }
  if (!stages.empty() || !run.outputs.stages.empty()) return stages;
  std::error_code error;
  for (fs::directory_iterator it(run.dir / "stages", error), end; !error && it != end; it.increment(error)) {
    if (it->path().extension() == ".png" && IsRegularFileNoFollow(it->path())) stages.push_back(it->path());
  }
  std::sort(stages.begin(), stages.end());
  return stages;
}

struct LogTail {
  std::string text;
  bool truncated = false;
};

LogTail ReadLogTail(const fs::path& log, std::size_t max_lines) {
  constexpr std::streamoff kMaxBytes = 64 * 1024;
  LogTail tail;
  std::ifstream in(log, std::ios::binary | std::ios::ate);
  if (!in) return tail;
  const std::streamoff size = in.tellg();
  const std::streamoff start = std::max<std::streamoff>(0, size - kMaxBytes);
  in.seekg(start);
  std::string content(static_cast<std::size_t>(size - start), '\0');
  in.read(content.data(), static_cast<std::streamsize>(content.size()));
  tail.truncated = start > 0;
  std::size_t lines = 0;
  std::size_t pos = content.size();
  if (pos > 0 && content[pos - 1] == '\n') --pos;
  while (pos > 0) {
    const std::size_t newline = content.rfind('\n', pos - 1);
    if (++lines > max_lines) {
      tail.truncated = true;
      break;
    }
    if (newline == std::string::npos) {
      pos = 0;
      break;
    }
    pos = newline;
  }
  tail.text = content.substr(pos == 0 ? 0 : pos + 1);
  return tail;
}

// Calls fn(i) for i in [0, n) on `threads` threads; fn must only touch data of its own i.
void ParallelFor(std::size_t n, int threads, const std::function<void(std::size_t)>& fn) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    for (std::size_t i = next++; i < n; i = next++) {
      try {
        fn(i);
      } catch (...) {
        std::lock_guard lock(failure_mutex);
        if (!failure) failure = std::current_exception();
      }
    }
  };
  {
    std::vector<std::jthread> pool;
    for (int t = 1; t < std::max(threads, 1); ++t) pool.emplace_back(worker);
    worker();
  }
  if (failure) std::rethrow_exception(failure);
}

// One image to make: `make` runs on a worker thread; `done` runs afterwards on the calling thread.
struct ImageJob {
  std::function<void()> make;
  std::function<void(const std::string& error)> done;  ///< error empty when made
};

void RunImageJobs(std::vector<ImageJob>& jobs, int threads) {
  std::vector<std::string> errors(jobs.size());
  ParallelFor(jobs.size(), threads, [&](std::size_t i) {
    try {
      jobs[i].make();
    } catch (const std::exception& error) {
      errors[i] = error.what();
      if (errors[i].empty()) errors[i] = "unknown error";
    }
  });
  for (std::size_t i = 0; i < jobs.size(); ++i) jobs[i].done(errors[i]);
}

struct PlotSpec {
  const MetricColumn* column;
  std::size_t index;
  bool trajectory;
};

std::vector<PlotRequest> PlanPlots(const SweepModel& model, const ReportLayout& layout, const fs::path& out_dir,
                                   SiteData& site) {
  std::vector<PlotRequest> requests;
  for (const SequenceModel& sequence : model.sequences) {
    std::vector<PlotSpec> specs;
    for (std::size_t c = 0; c < sequence.trajectory_columns.size(); ++c) {
      if (sequence.trajectory_columns[c].metric == "ape_trans")
        specs.push_back({&sequence.trajectory_columns[c], c, true});
    }
    for (std::size_t c = 0; c < sequence.map_columns.size(); ++c) specs.push_back({&sequence.map_columns[c], c, false});
    for (const PlotSpec& spec : specs) {
      const MetricColumn& column = *spec.column;
      std::size_t row_index = 0;
      PlotRequest request;
      request.title = sequence.title + ": " + column.title + (column.spec.empty() ? "" : ", " + column.spec);
      request.y_label = column.title + (column.unit.empty() ? "" : " (" + column.unit + ")");
      request.log_scale = true;
      for (const AlgorithmRow& row : sequence.rows) {
        const MetricCell& cell = spec.trajectory ? row.trajectory_cells[spec.index] : row.map_cells[spec.index];
        if (!cell.values.empty())
          request.series.push_back({row.algorithm, cell.values, RowStyle(site, sequence, row_index)});
        ++row_index;
      }
      if (request.series.empty()) continue;
      PlotArtifact artifact;
      artifact.metric = column.metric;
      artifact.title = request.title;
      artifact.path = layout.Plot(sequence.key, column.metric + (column.spec.empty() ? "" : "-" + column.spec));
      artifact.note = "no image maker configured";
      request.png = out_dir / artifact.path;
      site.plots[sequence.key].push_back(artifact);
      requests.push_back(std::move(request));
    }
  }
  return requests;
}

// A hard link where the file system allows (a report of 1,000 runs would otherwise copy every
// map and log), else a copy. The report is a snapshot to read, so sharing the bytes is safe.
void LinkOrCopy(const fs::path& from, const fs::path& to, std::error_code& error) {
  fs::remove(to, error);
  fs::create_hard_link(from, to, error);
  if (error) fs::copy_file(from, to, fs::copy_options::overwrite_existing, error);
}

void CopyDownloads(const RunRecord& run, const fs::path& run_out, RunArtifacts& artifacts) {
  for (const char* name : kDownloads) {
    if (!IsRegularFileNoFollow(run.dir / name)) continue;
    std::error_code error;
    LinkOrCopy(run.dir / name, run_out / name, error);
    if (error) {
      artifacts.notes.push_back(std::string(name) + " could not be copied: " + error.message());
    } else {
      artifacts.downloads.push_back(name);
    }
  }
  // The worker's stage animation is the page's animation as it is: no GIF to make.
  if (const std::optional<fs::path> animation = StageAnimation(run)) {
    std::error_code error;
    const fs::path shown = run_out / animation->filename();
    if (!IsRegularFileNoFollow(shown)) LinkOrCopy(*animation, shown, error);
    if (error) {
      artifacts.notes.push_back("Map-building animation not shown: " + error.message());
    } else {
      artifacts.animation = animation->filename().string();
    }
  }
}

// The runs the galleries show: each table row's median run.
std::vector<bool> GalleryRuns(const SweepModel& model) {
  std::vector<bool> in_gallery(model.runs.size(), false);
  for (const SequenceModel& sequence : model.sequences) {
    for (const AlgorithmRow& row : sequence.rows) {
      if (row.median_run) in_gallery[*row.median_run] = true;
    }
  }
  return in_gallery;
}

// Adds `name` to the run's downloads at its place in kDownloads' order.
void AddDownload(RunArtifacts& artifacts, const std::string& name) {
  auto rank = [](const std::string& file) {
    return std::find_if(std::begin(kDownloads), std::end(kDownloads), [&](const char* d) { return file == d; }) -
           std::begin(kDownloads);
  };
  const auto at = std::find_if(artifacts.downloads.begin(), artifacts.downloads.end(),
                               [&](const std::string& file) { return rank(file) > rank(name); });
  artifacts.downloads.insert(at, name);
}

// A run folder without map.geojson (the worker no longer stores one: it is traced from the map) gets it in
// the report for the runs whose own figures are drawn; `slamsweep vectorize` traces any other run's.
void PlanVectorMaps(const SweepModel& model, const ReportLayout& layout, const fs::path& out_dir,
                    const ReportOptions& options, SiteData& site, std::vector<ImageJob>& jobs) {
  const std::vector<bool> in_gallery = GalleryRuns(model);
  const bool every_run = options.run_figures_for_every_run || model.runs.size() <= options.figures_for_every_run_up_to;
  for (std::size_t i = 0; i < model.runs.size(); ++i) {
    const RunRecord& run = model.runs[i];
    if (!every_run && !in_gallery[i] && run.status == RunStatus::kOk) continue;
    if (IsRegularFileNoFollow(run.dir / "map.geojson") || !IsRegularFileNoFollow(run.dir / "map.yaml")) continue;
    const fs::path out = out_dir / layout.RunDir(i) / "map.geojson";
    RunArtifacts* artifacts = &site.runs[i];
    jobs.push_back({[map = run.dir / "map.yaml", out] { WriteVectorMapDownload(map, out); },
                    [artifacts, out](const std::string& error) {
                      if (error.empty() && IsRegularFileNoFollow(out)) {
                        AddDownload(*artifacts, "map.geojson");
                      } else {
                        artifacts->notes.push_back("Vector map (map.geojson) not made: " +
                                                   (error.empty() ? std::string("the file is missing") : error));
                      }
                    }});
  }
}

void PlanRunImages(const SweepModel& model, const ReportLayout& layout, const fs::path& out_dir,
                   const ReportOptions& options, SiteData& site, std::vector<ImageJob>& jobs) {
  Artwork* artwork = options.artwork;
  // Thumbnails are shown in the galleries (median runs) and on pages that have no overlay; other
  // runs skip them, which saves a third of the images of a large sweep.
  const std::vector<bool> in_gallery = GalleryRuns(model);
  // Beyond figures_for_every_run_up_to runs, a run's own figures are drawn for the runs the galleries show
  // (each row's median run) and for failed runs; the other pages say how to draw theirs.
  const bool every_run = options.run_figures_for_every_run || model.runs.size() <= options.figures_for_every_run_up_to;
  for (std::size_t i = 0; i < model.runs.size(); ++i) {
    const RunRecord& run = model.runs[i];
    const fs::path run_out = out_dir / layout.RunDir(i);
    RunArtifacts* artifacts = &site.runs[i];
    auto note = [artifacts](std::string what) {
      return [artifacts, what](const std::string& error) {
        if (!error.empty()) artifacts->notes.push_back(what + " not made: " + error);
      };
    };
    const fs::path map_image = MapImage(run);
    const bool has_map = IsRegularFileNoFollow(map_image);
    const bool can_overlay =
        has_map && IsRegularFileNoFollow(run.dir / "map.yaml") && IsRegularFileNoFollow(run.dir / "trajectory.tum");
    if (!every_run && !in_gallery[i] && run.status == RunStatus::kOk) {
      if (has_map) artifacts->figures_left_out = model.runs.size();
      if (!artifacts->animation.empty()) continue;
      // Run folders without a stage animation: their GIF is a figure to draw as well.
      if (!StagePaths(run).empty()) artifacts->figures_left_out = model.runs.size();
      continue;
    }
    if (has_map && (in_gallery[i] || !can_overlay)) {
      jobs.push_back({[=] { artwork->Thumbnail(map_image, run_out / "thumbnail.png", options.thumbnail_px); },
                      [artifacts, run_out, n = note("Map thumbnail")](const std::string& error) {
                        artifacts->thumbnail = error.empty() && IsRegularFileNoFollow(run_out / "thumbnail.png");
                        n(error);
                      }});
    }
    if (can_overlay) {
      const fs::path reference =
          IsRegularFileNoFollow(run.dir / "reference.tum") ? run.dir / "reference.tum" : fs::path();
      OverlaySettings overlay = OverlaySettingsOf(run);
      overlay.max_side_px = options.overlay_px;
      jobs.push_back({[=] {
                        artwork->TrajectoryOverlay(run.dir / "map.yaml", run.dir / "trajectory.tum", reference,
                                                   run_out / "trajectory.png", overlay);
                      },
                      [artifacts, run_out, n = note("Trajectory over the map")](const std::string& error) {
                        artifacts->overlay = error.empty() && IsRegularFileNoFollow(run_out / "trajectory.png");
                        n(error);
                      }});
    }
    std::vector<fs::path> stages = artifacts->animation.empty() ? StagePaths(run) : std::vector<fs::path>();
    if (!stages.empty()) {
      jobs.push_back({[=] { artwork->StagesGif(stages, run_out / "stages.gif", options.gif); },
                      [artifacts, run_out, n = note("Map-building animation")](const std::string& error) {
                        artifacts->gif = error.empty() && IsRegularFileNoFollow(run_out / "stages.gif");
                        n(error);
                      }});
    }
  }
}

// The paper service's text files per algorithm x sequence (files/<algorithm>/<sequence>/).
void WritePaperFiles(const SweepModel& model, const ReportLayout& layout, const fs::path& out_dir, SiteData& site) {
  std::error_code error;
  for (const SequenceModel& sequence : model.sequences) {
    for (const AlgorithmRow& row : sequence.rows) {
      if (row.runs.empty()) continue;  // a reference line has no runs and no files
      const fs::path files = out_dir / layout.FilesDir(row.algorithm, sequence.key);
      MakeDirectories(files);
      WriteTextFile(files / "rmse.txt", RmseText(sequence, row));
      WriteTextFile(files / "corners.txt", MapMetricText(sequence, row, "corners"));
      WriteTextFile(files / "occupied_ratio.txt", MapMetricText(sequence, row, "occupied_to_free_unknown"));
      if (row.median_run && IsRegularFileNoFollow(model.runs[*row.median_run].dir / "trajectory.tum")) {
        LinkOrCopy(model.runs[*row.median_run].dir / "trajectory.tum", files / "pose_log.tum", error);
        if (!error) site.pose_logs.insert({row.algorithm, sequence.key});
      }
    }
  }
}

// Links (else copies) RESULT_DIR/name into the report; false (and no stale copy left) when the sweep wrote none.
// The sweep replaces these files by rename, never in place, so a link keeps the report's version.
bool CopyResultFile(const fs::path& result_dir, const fs::path& out_dir, const char* name) {
  std::error_code error;
  if (!IsRegularFileNoFollow(result_dir / name)) {
    fs::remove(out_dir / name, error);
    return false;
  }
  LinkOrCopy(result_dir / name, out_dir / name, error);
  return !error;
}

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

}  // namespace slamsweep::report
