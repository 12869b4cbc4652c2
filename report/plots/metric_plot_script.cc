#include "report/plots/metric_plot_script.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "report/plots/gnuplot_string.h"

namespace slamsweep::report::inline plots {
namespace {

/// Half the width of the band the points of one algorithm are spread over, in x units.
constexpr double kJitterHalfWidth = 0.15;
constexpr double kMeanBarHalfWidth = 0.3;

struct PlotNumbers {
  double floor = 0.1;
  std::size_t at_floor = 0;
};

std::string Number(double value) { return fmt::format("{}", value); }

/// Where iteration `i` of `n` sits around the algorithm's position: evenly spread, so that
/// the plot is reproducible (no random jitter) and equal values stay distinguishable.
double JitterOffset(std::size_t i, std::size_t n) {
  if (n < 2) return 0.0;
  return -kJitterHalfWidth + 2.0 * kJitterHalfWidth * static_cast<double>(i) / static_cast<double>(n - 1);
}

}  // namespace

SeriesSpread ComputeSpread(std::span<const double> values) {
  SeriesSpread spread;
  double sum = 0.0;
  for (const double v : values) {
    if (!std::isfinite(v)) continue;
    sum += v;
    ++spread.n;
  }
  if (spread.n == 0) return spread;
  spread.mean = sum / static_cast<double>(spread.n);
  if (spread.n < 2) return spread;
  double squares = 0.0;
  for (const double v : values) {
    if (std::isfinite(v)) squares += (v - spread.mean) * (v - spread.mean);
  }
  spread.std = std::sqrt(squares / static_cast<double>(spread.n - 1));
  return spread;
}

double LogAxisFloor(const MetricPlot& plot) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const MetricSeries& series : plot.series) {
    for (const double v : series.values) {
      if (std::isfinite(v) && v > 0.0) smallest = std::min(smallest, v);
    }
  }
  if (!std::isfinite(smallest)) return 0.1;
  return std::pow(10.0, std::floor(std::log10(smallest)) - 1.0);
}

std::string PlotMarker(std::size_t index) { return fmt::format("SLAMSWEEP_PLOT {}", index); }

std::string MetricPlotScript(const MetricPlot& plot, const std::filesystem::path& png, std::size_t index) {
  PlotNumbers numbers;
  if (plot.log_scale) numbers.floor = LogAxisFloor(plot);
  // On a log axis a value <= 0 has no place: it is lifted to the floor (and counted).
  const auto drawn = [&](double v) {
    if (plot.log_scale && v <= 0.0) return numbers.floor;
    return v;
  };

  std::string points;
  std::string means;
  std::string bars;
  std::string xtics;
  bool any_point = false;
  bool long_labels = plot.series.size() > 5;
  for (std::size_t s = 0; s < plot.series.size(); ++s) {
    const MetricSeries& series = plot.series[s];
    const double x = static_cast<double>(s + 1);
    const std::uint32_t colour = series.style.rgb;
    const SeriesSpread spread = ComputeSpread(series.values);
    std::size_t drawn_index = 0;
    for (const double v : series.values) {
      if (!std::isfinite(v)) continue;
      if (plot.log_scale && v <= 0.0) ++numbers.at_floor;
      points += fmt::format("{} {} {} {}\n", Number(x + JitterOffset(drawn_index++, spread.n)), Number(drawn(v)),
                            colour, series.style.point_type);
    }
    if (spread.n > 0) {
      any_point = true;
      means += fmt::format("{} {} {}\n", Number(x), Number(drawn(spread.mean)), colour);
      if (spread.std) {
        bars += fmt::format("{} {} {} {} {}\n", Number(x), Number(drawn(spread.mean)),
                            Number(drawn(spread.mean - *spread.std)), Number(drawn(spread.mean + *spread.std)), colour);
      }
    }
    const std::string label =
        fmt::format("{} (n={})", series.algorithm.empty() ? "(unnamed)" : series.algorithm, spread.n);
    if (label.size() > 14) long_labels = true;
    if (!xtics.empty()) xtics += ", ";
    xtics += fmt::format("{} {}", GnuplotQuoted(label), Number(x));
  }

  std::string title = plot.title;
  if (numbers.at_floor > 0) {
    title += fmt::format(" ({} value{} <= 0 drawn at the axis floor {})", numbers.at_floor,
                         numbers.at_floor == 1 ? "" : "s", Number(numbers.floor));
  }
  if (!any_point) title += " (no data)";

  const std::string p = fmt::format("$points_{}", index);
  const std::string m = fmt::format("$means_{}", index);
  const std::string e = fmt::format("$bars_{}", index);
  std::string script;
  script += "reset\n";
  script += fmt::format("print {}\n", GnuplotQuoted(PlotMarker(index)));
  script += "set terminal pngcairo noenhanced size 800,480 font 'Sans,10'\n";
  script += fmt::format("set output {}\n", GnuplotQuoted(png.string()));
  script += fmt::format("set title {} noenhanced\n", GnuplotQuoted(title));
  script += fmt::format("set ylabel {} noenhanced\n", GnuplotQuoted(plot.y_label));
  script += "unset key\nset grid ytics\nset border 3\nset ytics nomirror\nset pointintervalbox 0\n";
  script += fmt::format("set xrange [0.4:{}]\n", Number(static_cast<double>(plot.series.size()) + 0.6));
  if (xtics.empty()) {
    script += "unset xtics\n";
  } else {
    script += fmt::format("set xtics ({}) nomirror{}\n", xtics, long_labels ? " rotate by -25 left" : "");
  }
  if (plot.log_scale) {
    script += "set logscale y\n";
    // The axis starts a little below the floor so that points at the floor are not half hidden by
    // the border; a dashed line and a "<= 0" tick mark the floor when values were lifted to it.
    const double bottom = numbers.floor / 1.5;
    script += any_point ? fmt::format("set yrange [{}:*]\n", Number(bottom))
                        : fmt::format("set yrange [{}:{}]\n", Number(bottom), Number(numbers.floor * 100));
    if (numbers.at_floor > 0) {
      script += fmt::format("set ytics add ('<= 0' {})\n", Number(numbers.floor));
      script += fmt::format(
          "set arrow from graph 0, first {0} to graph 1, first {0} nohead dashtype 2 "
          "linecolor rgb '#888888'\n",
          Number(numbers.floor));
    }
  }

  std::string clauses;
  const auto add_block = [&](const std::string& name, const std::string& rows, const std::string& how) {
    if (rows.empty()) return;
    script += name + " << EOD\n" + rows + "EOD\n";
    clauses += (clauses.empty() ? "" : ", ") + name + " " + how;
  };
  // Points last, so the mean bar does not hide a value lying on it.
  add_block(m, means,
            fmt::format("using ($1-{0}):2:({1}):(0):3 with vectors nohead linewidth 2.5 linecolor rgb variable",
                        Number(kMeanBarHalfWidth), Number(2 * kMeanBarHalfWidth)));
  add_block(e, bars, "using 1:2:3:4:5 with yerrorbars pointtype -1 linewidth 1.2 linecolor rgb variable");
  // Each algorithm's own marker (column 4), so that two algorithms of one colour stay apart.
  add_block(p, points, "using 1:2:4:3 with points pointtype variable pointsize 0.8 linecolor rgb variable");
  if (clauses.empty()) {
    // Nothing to draw: gnuplot refuses an empty plot, so it gets one point outside the x range.
    script += p + " << EOD\n-10 1\nEOD\n";
    clauses = p + " using 1:2 with points";
  }
  script += "plot " + clauses + "\n";
  script += "unset output\n";
  return script;
}

}  // namespace slamsweep::report::inline plots
