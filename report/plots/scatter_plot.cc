#include "report/plots/scatter_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "report/plots/gnuplot_batch.h"
#include "report/plots/gnuplot_string.h"
#include "report/plots/metric_plot_script.h"
#include "report/plots/view_figure_scripts.h"

namespace slamsweep::report::inline plots {
namespace {

/// Where the graded colours start on the heatmap scale: its palest yellow is too faint for a point on white.
constexpr double kLightestShade = 0.2;
constexpr std::size_t kKeyColumns = 3;
constexpr int kKeyRowPx = 14;

struct AxisRange {
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  bool all_positive = true;
  bool Logarithmic() const { return all_positive && std::isfinite(min) && min > 0.0 && max / min >= 10.0; }
};

bool Drawable(double x, double y) { return std::isfinite(x) && std::isfinite(y); }

}  // namespace

std::uint32_t GradedColour(std::size_t index, std::size_t count) {
  const double t = count < 2 ? 1.0 : static_cast<double>(index) / static_cast<double>(count - 1);
  return HeatmapColour(kLightestShade + (1.0 - kLightestShade) * t);
}

std::string ScatterPlotScript(const ScatterPlot& plot, const std::filesystem::path& png, std::size_t index) {
  AxisRange x_range, y_range;
  std::size_t points = 0;
  for (const ScatterSeries& series : plot.series) {
    for (std::size_t i = 0; i < std::min(series.x.size(), series.y.size()); ++i) {
      if (!Drawable(series.x[i], series.y[i])) continue;
      ++points;
      for (auto [range, v] : {std::pair{&x_range, series.x[i]}, std::pair{&y_range, series.y[i]}}) {
        range->min = std::min(range->min, v);
        range->max = std::max(range->max, v);
        range->all_positive = range->all_positive && v > 0.0;
      }
    }
  }
  // The key goes below the plot, where long labels ("odo-10 · icp-slam") take no width from it; the
  // picture grows by a line for every key row beyond two.
  const std::size_t key_rows = (plot.series.size() + kKeyColumns - 1) / kKeyColumns;
  const int height_px = 420 + kKeyRowPx * static_cast<int>(key_rows > 2 ? key_rows - 2 : 0);
  std::string script = "reset\n";
  script += fmt::format("print {}\n", GnuplotQuoted(PlotMarker(index)));
  script += fmt::format("set terminal pngcairo noenhanced size 560,{} font 'Sans,9'\n", height_px);
  script += fmt::format("set output {}\n", GnuplotQuoted(png.string()));
  script += fmt::format("set title {} noenhanced\n",
                        GnuplotQuoted(fmt::format("{} ({} run{})", plot.title, points, points == 1 ? "" : "s")));
  script += fmt::format("set xlabel {} noenhanced\n", GnuplotQuoted(plot.x_label));
  script += fmt::format("set ylabel {} noenhanced\n", GnuplotQuoted(plot.y_label));
  script += fmt::format("set grid\nset key below center horizontal Left reverse noenhanced maxcols {}\n", kKeyColumns);
  script += "set border 3\nset xtics nomirror\nset ytics nomirror\n";
  if (!plot.key_title.empty()) script += fmt::format("set key title {} noenhanced\n", GnuplotQuoted(plot.key_title));
  if (x_range.Logarithmic()) script += "set logscale x\n";
  if (y_range.Logarithmic()) script += "set logscale y\n";
  std::string clauses;
  for (std::size_t s = 0; s < plot.series.size(); ++s) {
    const ScatterSeries& series = plot.series[s];
    std::string rows;
    for (std::size_t i = 0; i < std::min(series.x.size(), series.y.size()); ++i) {
      if (Drawable(series.x[i], series.y[i])) rows += fmt::format("{} {}\n", series.x[i], series.y[i]);
    }
    if (rows.empty()) continue;
    const std::string block = fmt::format("$scatter_{}_{}", index, s);
    script += block + " << EOD\n" + rows + "EOD\n";
    clauses += fmt::format("{}{} using 1:2 with points pointtype {} pointsize 0.9 linecolor rgb '#{:06X}' title {}",
                           clauses.empty() ? "" : ", ", block, series.style.point_type, series.style.rgb,
                           GnuplotQuoted(series.label.empty() ? "(unnamed)" : series.label));
  }
  if (clauses.empty()) {
    // gnuplot refuses an empty plot: one invisible point outside the shown range.
    script += fmt::format("set xrange [0:1]\nset yrange [0:1]\n$scatter_{0}_none << EOD\n-10 -10\nEOD\n", index);
    clauses = fmt::format("$scatter_{}_none using 1:2 with points notitle", index);
  }
  script += "plot " + clauses + "\n";
  script += "unset output\n";
  return script;
}

void WriteScatterPlots(const std::vector<ScatterPlotJob>& jobs) {
  RunGnuplotJobs(jobs, [](const ScatterPlotJob& job, std::size_t i) {
    return GnuplotBatchJob{ScatterPlotScript(job.plot, job.png, i), job.png, job.plot.title};
  });
}

}  // namespace slamsweep::report::inline plots
