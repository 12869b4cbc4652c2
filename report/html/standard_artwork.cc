#include "report/html/standard_artwork.h"

#include "report/images/map_comparison.h"
#include "report/images/stages_gif.h"
#include "report/images/thumbnail.h"
#include "report/images/trajectory_overlay.h"
#include "report/plots/metric_plot.h"
#include "report/plots/scatter_plot.h"
#include "report/plots/view_figures.h"

namespace slamsweep::report::inline html {

namespace {

class StandardArtwork final : public Artwork {
 public:
  void Plots(const std::vector<PlotRequest>& plots) override {
    std::vector<MetricPlotJob> jobs;
    jobs.reserve(plots.size());
    for (const PlotRequest& request : plots) {
      MetricPlotJob job;
      job.plot.title = request.title;
      job.plot.y_label = request.y_label;
      job.plot.log_scale = request.log_scale;
      for (const PlotSeriesValues& series : request.series) {
        job.plot.series.push_back({series.algorithm, series.values, series.style});
      }
      job.png = request.png;
      jobs.push_back(std::move(job));
    }
    WriteMetricPlots(jobs);
  }

  void ScatterPlots(const std::vector<ScatterPlotJob>& plots) override { WriteScatterPlots(plots); }

  void Figures(const std::vector<FigureJob>& figures) override { WriteViewFigures(figures); }

  MapComparisonDrawn MapComparison(const MapComparisonJob& job) override { return WriteMapComparison(job); }

  void StagesGif(const std::vector<std::filesystem::path>& stage_pngs, const std::filesystem::path& gif,
                 const GifSettings& settings) override {
    GifOptions options;
    options.max_side_px = settings.max_side_px;
    options.max_bytes = settings.max_bytes;
    WriteStagesGif(stage_pngs, gif, options);
  }

  void StagesGifFromAnimation(const std::filesystem::path& animation, const std::filesystem::path& gif,
                              const GifSettings& settings) override {
    GifOptions options;
    options.max_side_px = settings.max_side_px;
    options.max_bytes = settings.max_bytes;
    WriteStagesGifFromAnimation(animation, gif, options);
  }

  void Thumbnail(const std::filesystem::path& map_image, const std::filesystem::path& png, int max_side_px) override {
    WriteThumbnail(map_image, png, max_side_px);
  }

  void TrajectoryOverlay(const std::filesystem::path& map_yaml, const std::filesystem::path& estimate_tum,
                         const std::filesystem::path& reference_tum, const std::filesystem::path& png,
                         const OverlaySettings& settings) override {
    OverlayOptions options;
    options.align = settings.align;
    options.t_max_diff_s = settings.t_max_diff_s;
    options.max_side_px = settings.max_side_px;
    WriteTrajectoryOverlay(map_yaml, estimate_tum, reference_tum, png, options);
  }
};

}  // namespace

std::unique_ptr<Artwork> MakeStandardArtwork() { return std::make_unique<StandardArtwork>(); }

bool StandardArtworkDrawsImages() { return true; }

}  // namespace slamsweep::report::inline html
