#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "report/images/map_comparison_types.h"
#include "report/plots/figure_types.h"
#include "report/plots/scatter_plot.h"

namespace slamsweep::report::inline html {

/// One algorithm's values in a metric plot (one per successful iteration).
struct PlotSeriesValues {
  PlotSeriesValues() = default;
  PlotSeriesValues(std::string algorithm_name, std::vector<double> series_values, SeriesStyle series_style = {})
      : algorithm(std::move(algorithm_name)), values(std::move(series_values)), style(series_style) {}

  std::string algorithm;
  std::vector<double> values;
  SeriesStyle style;  ///< the algorithm's colour and marker (AlgorithmPalette)
};

/// One metric plot of the paper's figures 3, 5, 6, 7 to draw into `png`.
struct PlotRequest {
  std::string title;
  std::string y_label;
  bool log_scale = true;
  std::vector<PlotSeriesValues> series;
  std::filesystem::path png;
};

/// Limits of the per-run animation.
struct GifSettings {
  int max_side_px = 480;
  std::size_t max_bytes = 2 * 1024 * 1024;  ///< the issue's cap: under 2 MB each
};

/// How the reference is placed on the estimate's map: the run's own evaluation settings
/// (run.json `evaluation`), so the picture agrees with the ATE it illustrates.
struct OverlaySettings {
  std::string align = "se2";
  double t_max_diff_s = 0.01;
  /// Longer side of the picture: the run page shows it at most 480 px wide (style.css), and a
  /// larger PNG only costs encoding time (overlays are most of a large report's time).
  int max_side_px = 480;
};

/// The images of the report, behind an interface so that pages can be generated and tested
/// without gnuplot or giflib (a fake writes tiny images). Every method may throw: WriteReport
/// catches it, leaves that image out and says why on the page. Methods are called from several
/// threads at once and must be thread-safe.
class Artwork {
 public:
  virtual ~Artwork() = default;
  /// Draws every plot (one call per report, so a gnuplot process can draw them all).
  virtual void Plots(const std::vector<PlotRequest>& plots) = 0;
  /// Draws every scatter plot of validity.html (one call per report, like Plots).
  virtual void ScatterPlots(const std::vector<ScatterPlotJob>& plots) = 0;
  /// Draws the figures of the segment-length and parameter pages (report/html/view_pages.h), one call per report.
  /// The default draws none (the pages then say the figures are missing), so an image maker written before
  /// these pages still builds.
  virtual void Figures(const std::vector<FigureJob>& figures);
  /// Draws one table's "Maps compared" panels and difference images (report/images/map_comparison.h), one
  /// call per table. The default draws none (the page then says the maps are missing).
  virtual MapComparisonDrawn MapComparison(const MapComparisonJob& job);
  /// An animated GIF of the stage maps, in order.
  virtual void StagesGif(const std::vector<std::filesystem::path>& stage_pngs, const std::filesystem::path& gif,
                         const GifSettings& settings) = 0;
  /// The same GIF from the worker's stage animation (one animated PNG of every stage map).
  virtual void StagesGifFromAnimation(const std::filesystem::path& animation, const std::filesystem::path& gif,
                                      const GifSettings& settings) = 0;
  /// A PNG of the map image (PGM or PNG) whose longer side is at most `max_side_px`.
  virtual void Thumbnail(const std::filesystem::path& map_image, const std::filesystem::path& png, int max_side_px) = 0;
  /// The estimated trajectory (and the reference, when `reference_tum` is not empty) over the map.
  virtual void TrajectoryOverlay(const std::filesystem::path& map_yaml, const std::filesystem::path& estimate_tum,
                                 const std::filesystem::path& reference_tum, const std::filesystem::path& png,
                                 const OverlaySettings& settings) = 0;
};

}  // namespace slamsweep::report::inline html
