#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "report/plots/figure_types.h"

namespace slamsweep::report::inline plots {

/// Gnuplot commands that draw one figure into `png` (pngcairo), self-contained like
/// MetricPlotScript: `reset`, the batch marker of `index`, datablocks named after `index`, and
/// `unset output` at the end. Every text is quoted (GnuplotQuoted) and drawn noenhanced.
///
/// Boxplot: per series a box (q1-q3, filled in the series' colour, hatched for a variant), whiskers,
/// a median line and the mean as the series' marker; series side by side within each category, the
/// key in series order; the title counts the outliers left out.
std::string BoxplotScript(const BoxplotFigure& figure, const std::filesystem::path& png, std::size_t index);

/// Lines with markers (dashed for a variant) and std whiskers; the highlighted point ringed and
/// named in the key.
std::string LineFigureScript(const LineFigure& figure, const std::filesystem::path& png, std::size_t index);

/// Cells coloured on a reversed viridis scale (light = low), each annotated with its text in black
/// or white, whichever reads on its colour; cells without value grey with "no run"; the best framed.
std::string HeatmapScript(const HeatmapFigure& figure, const std::filesystem::path& png, std::size_t index);

/// Paths at one scale (equal axes), the reference first in thick grey, the others in their colours; a series
/// with colour values drawn on the reversed viridis scale with a colour bar.
std::string PathFigureScript(const PathFigure& figure, const std::filesystem::path& png, std::size_t index);

/// The script of whichever figure `job` holds.
std::string FigureScript(const FigureJob& job, std::size_t index);

/// The colour a heatmap cell of value `t` (0 = lowest, 1 = highest of the figure) gets, 0xRRGGBB,
/// and whether its text is written in white (dark cells).
std::uint32_t HeatmapColour(double t);
bool HeatmapTextIsWhite(double t);

}  // namespace slamsweep::report::inline plots
