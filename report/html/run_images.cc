#include "report/html/run_images.h"

#include <optional>
#include <string>

#include "report/html/artwork.h"
#include "report/html/run_downloads.h"
#include "report/html/safe_name.h"
#include "report/html/trajectory_figures.h"
#include "report/html/vector_map_download.h"

namespace slamsweep::report::inline html {
namespace {

namespace fs = std::filesystem;

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

}  // namespace

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
    if (!artifacts->animation.empty()) {
      // The page plays the worker's animated PNG; the GIF of the same frames is its download.
      const fs::path animation = run_out / artifacts->animation;
      jobs.push_back({[=] { artwork->StagesGifFromAnimation(animation, run_out / "stages.gif", options.gif); },
                      [artifacts, run_out, n = note("Map-building GIF (stages.gif)")](const std::string& error) {
                        artifacts->gif = error.empty() && IsRegularFileNoFollow(run_out / "stages.gif");
                        if (artifacts->gif) AddDownload(*artifacts, "stages.gif");
                        n(error);
                      }});
    }
    std::vector<fs::path> stages = artifacts->animation.empty() ? StagePaths(run) : std::vector<fs::path>();
    if (!stages.empty()) {
      jobs.push_back({[=] { artwork->StagesGif(stages, run_out / "stages.gif", options.gif); },
                      [artifacts, run_out, n = note("Map-building animation")](const std::string& error) {
                        artifacts->gif = error.empty() && IsRegularFileNoFollow(run_out / "stages.gif");
                        if (artifacts->gif) AddDownload(*artifacts, "stages.gif");
                        n(error);
                      }});
    }
  }
}

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

}  // namespace slamsweep::report::inline html
