#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "report/plots/figure_types.h"

namespace slamsweep::report::inline plots {

/// One set of points drawn in one colour and marker, with its label in the key.
struct ScatterSeries {
  std::string label;
  SeriesStyle style;  ///< colour and marker (`variant` is not used)
  std::vector<double> x;
  std::vector<double> y;  ///< parallel to x
};

/// A scatter plot of one quantity against another: the validity study's "metric against real
/// error". An axis is logarithmic when all its finite values are positive and span a factor of 10
/// or more. Non-finite points are not drawn; the title says how many points are.
struct ScatterPlot {
  std::string title;
  std::string x_label;
  std::string y_label;
  /// Heads the key: what the colours and markers stand for ("colour: noise setting").
  std::string key_title;
  std::vector<ScatterSeries> series;
};

struct ScatterPlotJob {
  ScatterPlot plot;
  std::filesystem::path png;
};

/// Colour `index` of `count` graded settings, light (first) to dark (last), 0xRRGGBB: the heatmaps'
/// reversed viridis scale (HeatmapColour) without its palest fifth, so the lightest points still
/// show on white.
std::uint32_t GradedColour(std::size_t index, std::size_t count);

/// The gnuplot commands that draw `plot` into `png` (pngcairo, noenhanced text, data in datablocks
/// named after `index`), self-contained like MetricPlotScript, for one batch (RunGnuplotBatch).
std::string ScatterPlotScript(const ScatterPlot& plot, const std::filesystem::path& png, std::size_t index);

/// Draws every job as a PNG in one gnuplot process; throws like WriteMetricPlots.
void WriteScatterPlots(const std::vector<ScatterPlotJob>& jobs);

}  // namespace slamsweep::report::inline plots
