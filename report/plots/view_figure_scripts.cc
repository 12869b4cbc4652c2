#include "report/plots/view_figure_scripts.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "report/plots/gnuplot_string.h"
#include "report/plots/metric_plot_script.h"

namespace slamsweep::report::inline plots {
namespace {

std::string GnuplotNumber(double value) { return fmt::format("{}", value); }
std::string GnuplotColour(std::uint32_t rgb) { return fmt::format("'#{:06X}'", rgb); }

/// The common head of every figure: terminal, output, title, axis labels.
std::string Head(const std::string& title, const std::string& x_label, const std::string& y_label,
                 const std::filesystem::path& png, std::size_t index, int width_px, int height_px) {
  std::string script = "reset\n";
  script += fmt::format("print {}\n", GnuplotQuoted(PlotMarker(index)));
  script += fmt::format("set terminal pngcairo noenhanced size {},{} font 'Sans,10'\n", width_px, height_px);
  script += "set encoding utf8\n";
  script += fmt::format("set output {}\n", GnuplotQuoted(png.string()));
  script += fmt::format("set title {} noenhanced\n", GnuplotQuoted(title));
  script += fmt::format("set xlabel {} noenhanced\n", GnuplotQuoted(x_label));
  script += fmt::format("set ylabel {} noenhanced\n", GnuplotQuoted(y_label));
  return script;
}

/// Where the key goes, and how much taller the picture gets for it. Short labels: beside the plot;
/// long ones (a row label with its parameter values) would squeeze the plot, so they go below it,
/// in as many columns as fit, and the picture grows by their rows.
struct KeyPlacement {
  std::string command;
  int extra_height_px = 0;
};

KeyPlacement PlaceKey(const std::vector<std::string>& labels, int width_px, int sample_length) {
  std::size_t longest = 0;
  for (const std::string& label : labels) longest = std::max(longest, label.size());
  if (longest <= 28) {
    return {fmt::format("set key outside right top vertical Left reverse noenhanced samplen {}\n", sample_length), 0};
  }
  // About 7 px per character at 10 pt, plus the sample and gaps.
  const int column_px = 7 * static_cast<int>(longest) + 10 * sample_length + 30;
  const int columns = std::max(1, width_px / column_px);
  const int rows = (static_cast<int>(labels.size()) + columns - 1) / columns;
  return {fmt::format("set key outside below center horizontal Left reverse noenhanced samplen {} maxcols {}\n",
                      sample_length, columns),
          18 * rows};
}

/// Gnuplot refuses an empty plot: one invisible point outside every range stands in.
std::string EmptyPlot(std::size_t index) {
  return fmt::format("$empty_{0} << EOD\n-1e9 -1e9\nEOD\nplot $empty_{0} using 1:2 with points notitle\n", index);
}

std::string Datablock(const std::string& name, const std::string& rows) { return name + " << EOD\n" + rows + "EOD\n"; }

/// Hatch patterns of pngcairo for the variants after the first (a translucent solid fill for variant 0):
/// diagonals, then cross-hatches; never 3, which is solid, nor 0, which is empty.
std::string BoxFill(const SeriesStyle& style) {
  constexpr int kPatterns[] = {4, 5, 1, 6, 7, 2};
  if (style.variant == 0) return "fill transparent solid 0.45 border";
  return fmt::format("fill transparent pattern {} border", kPatterns[(style.variant - 1) % 6]);
}

int DashType(const SeriesStyle& style) { return 1 + style.variant % 5; }

struct ViridisStop {
  double t;
  std::uint32_t rgb;
};

// Viridis (matplotlib), reversed so that light is low: perceptually uniform, readable in grey and
// with colour-vision deficiencies.
constexpr std::array<ViridisStop, 5> kViridisReversed = {
    {{0.0, 0xFDE725}, {0.25, 0x5EC962}, {0.5, 0x21918C}, {0.75, 0x3B528B}, {1.0, 0x440154}}};

double Channel(std::uint32_t rgb, int shift) { return static_cast<double>((rgb >> shift) & 0xFF); }

double RelativeLuminance(std::uint32_t rgb) {
  const auto linear = [](double c) {
    c /= 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  return 0.2126 * linear(Channel(rgb, 16)) + 0.7152 * linear(Channel(rgb, 8)) + 0.0722 * linear(Channel(rgb, 0));
}

}  // namespace

std::uint32_t HeatmapColour(double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  for (std::size_t i = 1; i < kViridisReversed.size(); ++i) {
    const ViridisStop& a = kViridisReversed[i - 1];
    const ViridisStop& b = kViridisReversed[i];
    if (t > b.t) continue;
    const double f = (t - a.t) / (b.t - a.t);
    std::uint32_t rgb = 0;
    for (const int shift : {16, 8, 0}) {
      const double c = Channel(a.rgb, shift) + f * (Channel(b.rgb, shift) - Channel(a.rgb, shift));
      rgb |= static_cast<std::uint32_t>(std::lround(c)) << shift;
    }
    return rgb;
  }
  return kViridisReversed.back().rgb;
}

bool HeatmapTextIsWhite(double t) {
  // White text reads better than black below a relative luminance of about 0.18 (equal contrast ratio).
  return RelativeLuminance(HeatmapColour(t)) < 0.18;
}

std::string BoxplotScript(const BoxplotFigure& figure, const std::filesystem::path& png, std::size_t index) {
  const std::size_t series_count = figure.series.size();
  const std::size_t categories = figure.categories.size();
  const double slot = series_count == 0 ? 0.8 : 0.8 / static_cast<double>(series_count);
  const double box_width = 0.8 * slot;
  std::size_t outliers = 0;
  for (const BoxSeries& series : figure.series) {
    for (const auto& box : series.boxes) outliers += box ? box->outliers : 0;
  }
  std::string title = figure.title;
  if (outliers > 0) title += fmt::format(" ({} beyond the whiskers, not drawn)", outliers);
  const int width = std::clamp(360 + static_cast<int>(categories * series_count) * 22, 800, 1400);
  std::vector<std::string> labels;
  for (const BoxSeries& series : figure.series) {
    const bool empty =
        std::none_of(series.boxes.begin(), series.boxes.end(), [](const auto& box) { return box.has_value(); });
    labels.push_back(series.label + (empty ? " (no segments)" : ""));
  }
  const KeyPlacement key = PlaceKey(labels, width, 2);
  std::string script = Head(title, figure.x_label, figure.y_label, png, index, width, 500 + key.extra_height_px);
  script += key.command;
  script += "set grid ytics\nset border 3\nset ytics nomirror\nset yrange [0:*]\n";
  script += fmt::format("set xrange [0.5:{}]\n", GnuplotNumber(static_cast<double>(categories) + 0.5));
  std::string tics;
  for (std::size_t k = 0; k < categories; ++k) {
    tics += fmt::format("{}{} {}", k == 0 ? "" : ", ", GnuplotQuoted(figure.categories[k]), k + 1);
  }
  script += tics.empty() ? "unset xtics\n" : "set xtics (" + tics + ") nomirror scale 0\n";
  // Thin separators between the categories.
  for (std::size_t k = 1; k < categories; ++k) {
    script += fmt::format("set arrow from {0}, graph 0 to {0}, graph 1 nohead linecolor rgb '#DDDDDD'\n",
                          GnuplotNumber(static_cast<double>(k) + 0.5));
  }

  std::string clauses;
  for (std::size_t s = 0; s < series_count; ++s) {
    const BoxSeries& series = figure.series[s];
    const double offset = (static_cast<double>(s) - (static_cast<double>(series_count) - 1.0) / 2.0) * slot;
    std::string rows;
    for (std::size_t k = 0; k < categories && k < series.boxes.size(); ++k) {
      if (!series.boxes[k]) continue;
      const BoxStats& b = *series.boxes[k];
      rows += fmt::format("{} {} {} {} {} {} {}\n", GnuplotNumber(static_cast<double>(k + 1) + offset),
                          GnuplotNumber(b.q1), GnuplotNumber(b.whisker_low), GnuplotNumber(b.whisker_high),
                          GnuplotNumber(b.q3), GnuplotNumber(b.median), GnuplotNumber(b.mean));
    }
    const std::string name = fmt::format("$box_{}_{}", index, s);
    const std::string colour = GnuplotColour(series.style.rgb);
    if (rows.empty()) {
      // Still in the key, so that the legend lists every row of the table.
      clauses +=
          fmt::format("{}NaN with boxes {} fillcolor rgb {} linecolor rgb {} title {}", clauses.empty() ? "" : ", ",
                      BoxFill(series.style), colour, colour, GnuplotQuoted(series.label + " (no segments)"));
      continue;
    }
    script += Datablock(name, rows);
    const std::string width_column = fmt::format("({})", GnuplotNumber(box_width));
    clauses += fmt::format(
        "{}{} using 1:2:3:4:5:{} with candlesticks whiskerbars 0.6 {} fillcolor rgb {} linecolor rgb {} linewidth 1.3 "
        "title {}",
        clauses.empty() ? "" : ", ", name, width_column, BoxFill(series.style), colour, colour,
        GnuplotQuoted(series.label));
    // The median in black, or white on a dark colour (black, dark grey) where black would vanish.
    const bool dark = RelativeLuminance(series.style.rgb) < 0.1;
    clauses += fmt::format(", {} using 1:6:6:6:6:{} with candlesticks linecolor rgb {} linewidth 2 notitle", name,
                           width_column, dark ? "'#FFFFFF'" : "'#000000'");
    // The mean as the algorithm's marker, outlined in black so it shows on its own box.
    clauses += fmt::format(
        ", {0} using 1:7 with points pointtype {1} pointsize 1.25 linecolor rgb '#000000' notitle"
        ", {0} using 1:7 with points pointtype {1} pointsize 0.85 linecolor rgb {2} notitle",
        name, series.style.point_type, colour);
  }
  script += clauses.empty() ? EmptyPlot(index) : "plot " + clauses + "\n";
  script += "unset output\n";
  return script;
}

std::string LineFigureScript(const LineFigure& figure, const std::filesystem::path& png, std::size_t index) {
  // Many series: a wide picture with the key beside or below the plot; a few: small enough to be shown
  // two by two without shrinking the text much, the key below the plot, where it hides no point.
  const bool many = figure.series.size() > 3;
  std::vector<std::string> labels;
  for (const LineSeries& series : figure.series) labels.push_back(series.label);
  if (figure.highlight) labels.push_back(figure.highlight->label);
  KeyPlacement key = PlaceKey(labels, many ? 960 : 640, 3);
  if (!many) key = {"set key below horizontal Left reverse noenhanced samplen 3\n", 0};
  std::string script = Head(figure.title, figure.x_label, figure.y_label, png, index, many ? 960 : 640,
                            (many ? 480 : 420) + key.extra_height_px);
  script += key.command;
  script += "set grid xtics ytics\nset border 3\nset xtics nomirror\nset ytics nomirror\n";
  double x_min = std::numeric_limits<double>::infinity();
  double x_max = -std::numeric_limits<double>::infinity();
  double y_min = std::numeric_limits<double>::infinity();
  for (const LineSeries& series : figure.series) {
    for (const LinePoint& point : series.points) {
      x_min = std::min(x_min, point.x);
      x_max = std::max(x_max, point.x);
      y_min = std::min(y_min, point.y - point.spread.value_or(0.0));
    }
  }
  const bool categorical = !figure.x_tics.empty();
  if (categorical) {
    std::string tics;
    for (std::size_t i = 0; i < figure.x_tics.size(); ++i) {
      tics += fmt::format("{}{} {}", i == 0 ? "" : ", ", GnuplotQuoted(figure.x_tics[i]), i);
    }
    script += "set xtics (" + tics + ")\n";
    script += fmt::format("set xrange [-0.5:{}]\n", GnuplotNumber(static_cast<double>(figure.x_tics.size()) - 0.5));
  } else if (figure.log_x) {
    script += "set logscale x\n";
    if (std::isfinite(x_min))
      script += fmt::format("set xrange [{}:{}]\n", GnuplotNumber(x_min / 1.3), GnuplotNumber(x_max * 1.3));
  } else if (std::isfinite(x_min)) {
    const double margin = x_max > x_min ? 0.06 * (x_max - x_min) : std::max(1.0, std::abs(x_min) * 0.1);
    script += fmt::format("set xrange [{}:{}]\n", GnuplotNumber(x_min - margin), GnuplotNumber(x_max + margin));
  }
  if (!categorical) {
    // A tic at every value drawn (parameter values, segment lengths), when they are few.
    std::vector<double> xs;
    for (const LineSeries& series : figure.series) {
      for (const LinePoint& point : series.points) xs.push_back(point.x);
    }
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    if (!xs.empty() && xs.size() <= 12) {
      std::string tics;
      for (const double x : xs) tics += fmt::format("{}{}", tics.empty() ? "" : ", ", GnuplotNumber(x));
      script += "set xtics (" + tics + ")\n";
    }
  }
  // Errors are never negative: start at 0 unless a whisker reaches below it.
  script += std::isfinite(y_min) && y_min >= 0.0 ? "set yrange [0:*]\n" : "set yrange [*:*]\n";

  const std::size_t count = figure.series.size();
  std::string clauses;
  for (std::size_t s = 0; s < count; ++s) {
    const LineSeries& series = figure.series[s];
    // A small sideways dodge keeps the whiskers of neighbouring series from covering each other.
    const double dodge_unit = categorical ? 0.06 : (figure.log_x ? 0.0 : 0.008 * std::max(x_max - x_min, 1e-9));
    const double dodge = (static_cast<double>(s) - (static_cast<double>(count) - 1.0) / 2.0) * dodge_unit;
    const auto x_of = [&](double x) { return figure.log_x ? x * std::pow(1.015, static_cast<double>(s)) : x + dodge; };
    std::string rows;
    std::string bars;
    for (const LinePoint& point : series.points) {
      rows += fmt::format("{} {}\n", GnuplotNumber(x_of(point.x)), GnuplotNumber(point.y));
      if (point.spread) {
        bars += fmt::format("{} {} {} {}\n", GnuplotNumber(x_of(point.x)), GnuplotNumber(point.y),
                            GnuplotNumber(point.y - *point.spread), GnuplotNumber(point.y + *point.spread));
      }
    }
    const std::string colour = GnuplotColour(series.style.rgb);
    const std::string name = fmt::format("$line_{}_{}", index, s);
    if (rows.empty()) continue;
    script += Datablock(name, rows);
    if (!bars.empty()) {
      script += Datablock(name + "_bars", bars);
      clauses +=
          fmt::format("{}{}_bars using 1:2:3:4 with yerrorbars pointtype -1 linecolor rgb {} linewidth 1.2 notitle",
                      clauses.empty() ? "" : ", ", name, colour);
    }
    clauses += fmt::format(
        "{}{} using 1:2 with linespoints linewidth 2 dashtype {} pointtype {} pointsize 1.1 linecolor rgb {} title {}",
        clauses.empty() ? "" : ", ", name, DashType(series.style), series.style.point_type, colour,
        GnuplotQuoted(series.label));
  }
  if (figure.highlight && figure.highlight->series < count &&
      figure.highlight->point < figure.series[figure.highlight->series].points.size()) {
    const LinePoint& point = figure.series[figure.highlight->series].points[figure.highlight->point];
    const std::string name = fmt::format("$best_{}", index);
    script += Datablock(name, fmt::format("{} {}\n", GnuplotNumber(point.x), GnuplotNumber(point.y)));
    clauses +=
        fmt::format("{}{} using 1:2 with points pointtype 6 pointsize 3 linewidth 2 linecolor rgb '#000000' title {}",
                    clauses.empty() ? "" : ", ", name, GnuplotQuoted(figure.highlight->label));
  }
  script += clauses.empty() ? EmptyPlot(index) : "plot " + clauses + "\n";
  script += "unset output\n";
  return script;
}

std::string HeatmapScript(const HeatmapFigure& figure, const std::filesystem::path& png, std::size_t index) {
  const std::size_t width = figure.x_values.size();
  const std::size_t height = figure.y_values.size();
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();
  for (const auto& line : figure.cells) {
    for (const HeatmapCell& cell : line) {
      if (cell.value && std::isfinite(*cell.value)) {
        low = std::min(low, *cell.value);
        high = std::max(high, *cell.value);
      }
    }
  }
  const bool any = std::isfinite(low);
  const double span = any && high > low ? high - low : 0.0;
  const auto t_of = [&](double v) { return span > 0.0 ? (v - low) / span : 0.5; };

  const int width_px = std::clamp(260 + static_cast<int>(width) * 110, 640, 1400);
  const int height_px = std::clamp(180 + static_cast<int>(height) * 60, 360, 1000);
  std::string script = Head(figure.title, figure.x_label, figure.y_label, png, index, width_px, height_px);
  script += "unset key\nset border 0\nset tics scale 0\nset size ratio -1\n";
  std::string palette;
  for (std::size_t i = 0; i < kViridisReversed.size(); ++i) {
    palette += fmt::format("{}{} '#{:06X}'", i == 0 ? "" : ", ", GnuplotNumber(kViridisReversed[i].t),
                           kViridisReversed[i].rgb);
  }
  script += "set palette defined (" + palette + ")\n";
  if (any) {
    const double pad = span > 0.0 ? 0.0 : std::max(std::abs(low) * 0.01, 1e-12);
    script += fmt::format("set cbrange [{}:{}]\n", GnuplotNumber(low - pad), GnuplotNumber(high + pad));
    script += fmt::format("set cblabel {} noenhanced\n", GnuplotQuoted(figure.value_label));
  } else {
    script += "unset colorbox\n";
  }
  std::string xtics;
  for (std::size_t x = 0; x < width; ++x) {
    xtics += fmt::format("{}{} {}", x == 0 ? "" : ", ", GnuplotQuoted(figure.x_values[x]), x);
  }
  std::string ytics;
  for (std::size_t y = 0; y < height; ++y) {
    ytics += fmt::format("{}{} {}", y == 0 ? "" : ", ", GnuplotQuoted(figure.y_values[y]), y);
  }
  script += xtics.empty() ? "unset xtics\n" : "set xtics (" + xtics + ")\n";
  script += ytics.empty() ? "unset ytics\n" : "set ytics (" + ytics + ")\n";
  script += fmt::format("set xrange [-0.5:{}]\nset yrange [-0.5:{}]\n", GnuplotNumber(static_cast<double>(width) - 0.5),
                        GnuplotNumber(static_cast<double>(height) - 0.5));

  std::string values;
  int object = 1;
  for (std::size_t y = 0; y < height && y < figure.cells.size(); ++y) {
    for (std::size_t x = 0; x < width && x < figure.cells[y].size(); ++x) {
      const HeatmapCell& cell = figure.cells[y][x];
      const bool has_value = cell.value && std::isfinite(*cell.value);
      const std::string xs = GnuplotNumber(static_cast<double>(x));
      const std::string ys = GnuplotNumber(static_cast<double>(y));
      if (has_value) {
        values += fmt::format("{} {} {}\n", xs, ys, GnuplotNumber(*cell.value));
      } else {
        script += fmt::format(
            "set object {} rectangle from {},{} to {},{} fillcolor rgb '#E0E0E0' fillstyle solid 1.0 noborder behind\n",
            object++, GnuplotNumber(x - 0.5), GnuplotNumber(y - 0.5), GnuplotNumber(x + 0.5), GnuplotNumber(y + 0.5));
      }
      const std::string text = has_value ? cell.text : (cell.text.empty() ? "no run" : cell.text);
      const bool white = has_value && HeatmapTextIsWhite(t_of(*cell.value));
      script += fmt::format("set label {} at {},{} center front textcolor rgb {} noenhanced\n", GnuplotQuoted(text), xs,
                            ys, white ? "'#FFFFFF'" : "'#000000'");
      if (cell.best) {
        script += fmt::format(
            "set object {} rectangle from {},{} to {},{} fillstyle empty border linecolor rgb '#D55E00' linewidth 4 "
            "front\n",
            object++, GnuplotNumber(x - 0.46), GnuplotNumber(y - 0.46), GnuplotNumber(x + 0.46),
            GnuplotNumber(y + 0.46));
      }
    }
  }
  if (values.empty()) {
    script += EmptyPlot(index);
  } else {
    const std::string name = fmt::format("$heat_{}", index);
    script += Datablock(name, values);
    // Each value a 1 x 1 cell: centre, half widths 0.5, coloured by the palette.
    script += fmt::format(
        "plot {} using 1:2:(0.5):(0.5):3 with boxxyerror fillstyle solid 1.0 noborder linecolor palette\n", name);
  }
  script += "unset output\n";
  return script;
}

std::string PathFigureScript(const PathFigure& figure, const std::filesystem::path& png, std::size_t index) {
  std::vector<std::string> labels;
  bool coloured = false;
  for (const PathSeries& series : figure.series) {
    labels.push_back(series.label);
    coloured = coloured || !series.colour_values.empty();
  }
  const int width_px = 900;
  const KeyPlacement key = PlaceKey(labels, width_px, 3);
  std::string script =
      Head(figure.title, figure.x_label, figure.y_label, png, index, width_px, 720 + key.extra_height_px);
  script += key.command;
  script += "set size ratio -1\nset grid\n";
  if (coloured) {
    std::string palette;
    for (std::size_t i = 0; i < kViridisReversed.size(); ++i) {
      palette += fmt::format("{}{} '#{:06X}'", i == 0 ? "" : ", ", GnuplotNumber(kViridisReversed[i].t),
                             kViridisReversed[i].rgb);
    }
    script += "set palette defined (" + palette + ")\n";
    script += fmt::format("set cblabel {} noenhanced\n", GnuplotQuoted(figure.colour_label));
  } else {
    script += "unset colorbox\n";
  }
  std::string clauses;
  for (std::size_t s = 0; s < figure.series.size(); ++s) {
    const PathSeries& series = figure.series[s];
    std::string rows;
    const bool by_colour = series.colour_values.size() == series.x.size() && !series.x.empty();
    for (std::size_t i = 0; i < series.x.size() && i < series.y.size(); ++i) {
      if (!std::isfinite(series.x[i]) || !std::isfinite(series.y[i])) continue;
      rows += by_colour ? fmt::format("{} {} {}\n", GnuplotNumber(series.x[i]), GnuplotNumber(series.y[i]),
                                      GnuplotNumber(series.colour_values[i]))
                        : fmt::format("{} {}\n", GnuplotNumber(series.x[i]), GnuplotNumber(series.y[i]));
    }
    if (rows.empty()) continue;
    const std::string name = fmt::format("$path_{}_{}", index, s);
    script += Datablock(name, rows);
    std::string style;
    if (series.reference) {
      style = "with lines linewidth 4 linecolor rgb '#A0A0A0'";
    } else if (by_colour) {
      style = "using 1:2:3 with lines linewidth 2.5 linecolor palette";
    } else {
      style = fmt::format("with lines linewidth 1.5 linecolor rgb {}{}", GnuplotColour(series.style.rgb),
                          series.style.variant > 0 ? " dashtype 2" : "");
    }
    if (!by_colour) style = "using 1:2 " + style;
    clauses += fmt::format("{}{} {} title {}", clauses.empty() ? "" : ", ", name, style, GnuplotQuoted(series.label));
  }
  script += clauses.empty() ? EmptyPlot(index) : "plot " + clauses + "\n";
  script += "unset output\n";
  return script;
}

std::string FigureScript(const FigureJob& job, std::size_t index) {
  return std::visit(
      [&](const auto& figure) -> std::string {
        using T = std::decay_t<decltype(figure)>;
        if constexpr (std::is_same_v<T, BoxplotFigure>) {
          return BoxplotScript(figure, job.png, index);
        } else if constexpr (std::is_same_v<T, LineFigure>) {
          return LineFigureScript(figure, job.png, index);
        } else if constexpr (std::is_same_v<T, PathFigure>) {
          return PathFigureScript(figure, job.png, index);
        } else {
          return HeatmapScript(figure, job.png, index);
        }
      },
      job.figure);
}

const std::string& FigureTitle(const ViewFigure& figure) {
  return std::visit([](const auto& f) -> const std::string& { return f.title; }, figure);
}

}  // namespace slamsweep::report::inline plots
