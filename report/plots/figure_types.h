#pragma once

// The figures of the report's segment-length and parameter pages, as data: the pages plan them,
// an Artwork draws them (gnuplot in report/plots/view_figures.h, a stand-in in tests).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "report/model/box_summary.h"

namespace slamsweep::report::inline plots {

/// How one series is drawn: its algorithm's colour and marker (AlgorithmPalette), and `variant`
/// for the second, third, ... row of the same algorithm in one figure (other parameter values):
/// dashed lines and hatched boxes tell them apart while the colour still names the algorithm.
struct SeriesStyle {
  std::uint32_t rgb = 0x0072B2;
  int point_type = 7;
  int variant = 0;
};

/// Box statistics as drawn: the report model's Tukey box.
using BoxStats = BoxSummary;

struct BoxSeries {
  std::string label;
  SeriesStyle style;
  std::vector<std::optional<BoxStats>> boxes;  ///< parallel to BoxplotFigure::categories
};

/// Boxes side by side: one group per category (segment length) on the x axis, one box per series
/// within it, in series order (= the table's row order, = the legend's order).
struct BoxplotFigure {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<std::string> categories;
  std::vector<BoxSeries> series;
};

struct LinePoint {
  double x = 0.0;
  double y = 0.0;
  std::optional<double> spread;  ///< whisker half-length (std); none for one value
  std::size_t n = 0;
};

struct LineSeries {
  std::string label;
  SeriesStyle style;
  std::vector<LinePoint> points;
};

/// Lines through points with whiskers. A categorical x axis (`x_tics` set) places category i at x = i.
/// `highlight` rings one point of one series (the best parameter value).
struct LineFigure {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<LineSeries> series;
  std::vector<std::string> x_tics;  ///< empty: numeric x axis
  bool log_x = false;
  struct Highlight {
    std::size_t series = 0;
    std::size_t point = 0;
    std::string label;
  };
  std::optional<Highlight> highlight;
};

struct HeatmapCell {
  std::optional<double> value;  ///< none: no run (drawn grey)
  std::string text;             ///< written in the cell
  bool best = false;            ///< framed
};

/// A grid of values, each cell annotated; colours run from light (low, better) to dark (high)
/// on a colour-blind-safe sequential scale.
struct HeatmapFigure {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::string value_label;  ///< the colour bar's label
  std::vector<std::string> x_values;
  std::vector<std::string> y_values;
  std::vector<std::vector<HeatmapCell>> cells;  ///< [y][x]
};

/// One path in the plane: a trajectory's x and y.
struct PathSeries {
  std::string label;
  SeriesStyle style;
  std::vector<double> x;
  std::vector<double> y;
  bool reference = false;  ///< drawn first, thick and grey, under the others
  /// When not empty (parallel to x): the path is coloured by these values on a sequential scale
  /// (evo's error-along-the-path plot) instead of its style's colour.
  std::vector<double> colour_values;
};

/// Paths over one another at one scale (equal axes): every row's trajectory over the reference, or
/// one trajectory coloured by its error along the path.
struct PathFigure {
  std::string title;
  std::string x_label = "x (m)";
  std::string y_label = "y (m)";
  std::string colour_label;  ///< the colour bar's label, for a series with colour_values
  std::vector<PathSeries> series;
};

using ViewFigure = std::variant<BoxplotFigure, LineFigure, HeatmapFigure, PathFigure>;

/// A figure to draw into `png`.
struct FigureJob {
  ViewFigure figure;
  std::filesystem::path png;
};

/// The title of any figure.
const std::string& FigureTitle(const ViewFigure& figure);

}  // namespace slamsweep::report::inline plots
