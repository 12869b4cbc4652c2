#pragma once

#include <vector>

#include "report/plots/figure_types.h"

namespace slamsweep::report::inline plots {

/// Draws every figure as a PNG in one gnuplot process (view_figure_scripts.h). Throws
/// std::runtime_error naming the first figure that could not be drawn and quoting gnuplot.
void WriteViewFigures(const std::vector<FigureJob>& jobs);

}  // namespace slamsweep::report::inline plots
