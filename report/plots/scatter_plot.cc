#include "report/plots/scatter_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "report/plots/gnuplot_string.h"
#include "report/plots/metric_plot_script.h"
#include "report/plots/plot_batch.h"

namespace slamsweep::report {
namespace {

/// Anchors of a light-to-dark ramp (viridis, reversed, its palest yellow darkened to show on white):
/// graded settings read in order.
constexpr std::array<std::array<double, 3>, 5> kRamp = {{{0.80, 0.72, 0.05},
                                                         {0.37, 0.79, 0.38},
                                                         {0.13, 0.57, 0.55},
                                                         {0.23, 0.32, 0.55},
                                                         {0.27, 0.00, 0.33}}};

std::string RampColour(std::size_t index, std::size_t count) {
  const double t = count < 2 ? 1.0 : static_cast<double>(index) / static_cast<double>(count - 1);
  const double position = t * static_cast<double>(kRamp.size() - 1);
  const std::size_t low = std::min(static_cast<std::size_t>(position), kRamp.size() - 2);
  const double fraction = position - static_cast<double>(low);
  std::array<int, 3> rgb{};
  for (std::size_t c = 0; c < 3; ++c) {
    const double value = kRamp[low][c] + fraction * (kRamp[low + 1][c] - kRamp[low][c]);
    rgb[c] = static_cast<int>(std::lround(255.0 * value));
  }
  return fmt::format("#{:02x}{:02x}{:02x}", rgb[0], rgb[1], rgb[2]);
}

struct AxisRange {
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  bool all_positive = true;
  bool Logarithmic() const { return all_positive && std::isfinite(min) && min > 0.0 && max / min >= 10.0; }
};

bool Drawable(double x, double y) { return std::isfinite(x) && std::isfinite(y); }

}  // namespace

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
  std::string script = "reset\n";
  script += fmt::format("print {}\n", GnuplotQuoted(PlotMarker(index)));
  script += "set terminal pngcairo noenhanced size 560,420 font 'Sans,9'\n";
  script += fmt::format("set output {}\n", GnuplotQuoted(png.string()));
  script += fmt::format("set title {} noenhanced\n",
                        GnuplotQuoted(fmt::format("{} ({} run{})", plot.title, points, points == 1 ? "" : "s")));
  script += fmt::format("set xlabel {} noenhanced\n", GnuplotQuoted(plot.x_label));
  script += fmt::format("set ylabel {} noenhanced\n", GnuplotQuoted(plot.y_label));
  script += "set grid\nset key outside right top noenhanced\nset border 3\nset xtics nomirror\nset ytics nomirror\n";
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
    clauses += fmt::format("{}{} using 1:2 with points pointtype 7 pointsize 0.9 linecolor rgb '{}' title {}",
                           clauses.empty() ? "" : ", ", block, RampColour(s, plot.series.size()),
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
  std::vector<PlotScript> scripts;
  scripts.reserve(jobs.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    scripts.push_back({jobs[i].plot.title, jobs[i].png, ScatterPlotScript(jobs[i].plot, jobs[i].png, i)});
  }
  DrawPlotScripts(scripts);
}

}  // namespace slamsweep::report
