#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "report/plots/metric_plot.h"

namespace slamsweep::report::inline plots {

/// Mean and sample standard deviation of the finite values of one series.
struct SeriesSpread {
  std::size_t n = 0;
  double mean = 0.0;
  /// Undefined (nullopt) below two values.
  std::optional<double> std;
};
SeriesSpread ComputeSpread(std::span<const double> values);

/// The log axis's floor for `plot`: one decade below the smallest positive finite value (a
/// power of ten), or 0.1 when no value is positive. Meaningless for a linear axis.
double LogAxisFloor(const MetricPlot& plot);

/// The marker line job `index` prints on gnuplot's stderr before it draws, so that an error
/// message can be traced to its plot.
std::string PlotMarker(std::size_t index);

/// The gnuplot commands that draw `plot` into `png` (pngcairo), self-contained: they start with
/// `reset` and end with `unset output` (which closes the PNG). Data go inline in datablocks named
/// after `index`, so that one gnuplot process can run the scripts of many plots in a row.
std::string MetricPlotScript(const MetricPlot& plot, const std::filesystem::path& png, std::size_t index);

}  // namespace slamsweep::report::inline plots
