#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "report/plots/figure_types.h"

namespace slamsweep::report::inline plots {

/// One algorithm's values of a metric on one sequence, one value per iteration (failed runs
/// are left out by the caller: they have no value, and the tables count them).
struct MetricSeries {
  MetricSeries() = default;
  MetricSeries(std::string algorithm_name, std::vector<double> series_values, SeriesStyle series_style = {})
      : algorithm(std::move(algorithm_name)), values(std::move(series_values)), style(series_style) {}

  std::string algorithm;
  std::vector<double> values;
  /// The algorithm's colour and marker in every plot of the report (AlgorithmPalette).
  SeriesStyle style;
};

/// The paper's figures 3, 5, 6, 7: algorithms side by side on a categorical x axis, every
/// iteration a point (small horizontal jitter), the mean as a horizontal bar and mean +- std
/// (sample std, n - 1) as an error bar; none when there is a single iteration, where std is
/// undefined. Non-finite values are not drawn (an algorithm's tick label gives n drawn).
struct MetricPlot {
  std::string title;
  std::string y_label;
  bool log_scale = true;
  std::vector<MetricSeries> series;
};

struct MetricPlotJob {
  MetricPlot plot;
  std::filesystem::path png;
};

/// Draws every job as a PNG (gnuplot's pngcairo terminal; PNG, not SVG, because gnuplot's SVG
/// carries inline styles and scripts that a Content-Security-Policy blocks). ONE gnuplot process
/// draws all jobs, since starting gnuplot costs far more than drawing a plot. Titles, labels and
/// algorithm names may hold any text: they are quoted for gnuplot and drawn without markup.
/// On a log axis, values <= 0 (and error bars reaching below it) are drawn at the axis floor, a
/// decade below the smallest positive value, and the title says how many were.
/// Throws std::runtime_error naming the plot's title and PNG and quoting gnuplot's stderr when a
/// plot fails or its PNG is missing, or when gnuplot cannot be started. Does nothing for no jobs.
void WriteMetricPlots(const std::vector<MetricPlotJob>& jobs);

}  // namespace slamsweep::report::inline plots
