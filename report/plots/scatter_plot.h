#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace slamsweep::report {

/// One coloured set of points (one noise setting, say), drawn with its label in the key.
struct ScatterSeries {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;  ///< parallel to x
};

/// A scatter plot of one quantity against another: the validity study's "metric against real
/// error". Series are coloured along an ordered ramp (light to dark, in their given order), since
/// they are graded settings. An axis is logarithmic when all its finite values are positive and
/// span a factor of 10 or more. Non-finite points are not drawn; the title says how many points are.
struct ScatterPlot {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<ScatterSeries> series;
};

struct ScatterPlotJob {
  ScatterPlot plot;
  std::filesystem::path png;
};

/// The gnuplot commands that draw `plot` into `png` (pngcairo, noenhanced text, data in datablocks
/// named after `index`), self-contained like MetricPlotScript, for one batch (DrawPlotScripts).
std::string ScatterPlotScript(const ScatterPlot& plot, const std::filesystem::path& png, std::size_t index);

/// Draws every job as a PNG in one gnuplot process; throws like WriteMetricPlots.
void WriteScatterPlots(const std::vector<ScatterPlotJob>& jobs);

}  // namespace slamsweep::report
