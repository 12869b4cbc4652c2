#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace slamsweep::report {

/// One plot of a batch: a self-contained gnuplot script that prints PlotMarker(index) first (its
/// position in the batch) and closes `png` at the end (see MetricPlotScript).
struct PlotScript {
  std::string title;
  std::filesystem::path png;
  std::string script;
};

/// Runs every script in ONE gnuplot process (starting gnuplot costs far more than drawing a
/// plot). Stale PNGs are removed first, so a failed plot never passes for a new one. Throws
/// std::runtime_error naming the plot's title and PNG and quoting gnuplot's stderr when a plot
/// fails or its PNG is missing, or when gnuplot cannot be started. Does nothing for no scripts.
void DrawPlotScripts(const std::vector<PlotScript>& plots);

}  // namespace slamsweep::report
