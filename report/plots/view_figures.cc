#include "report/plots/view_figures.h"

#include "report/plots/gnuplot_batch.h"
#include "report/plots/view_figure_scripts.h"

namespace slamsweep::report {

void WriteViewFigures(const std::vector<FigureJob>& jobs) {
  std::vector<GnuplotBatchJob> batch;
  batch.reserve(jobs.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) batch.push_back({FigureScript(jobs[i], i), jobs[i].png, FigureTitle(jobs[i].figure)});
  RunGnuplotBatch(batch);
}

}  // namespace slamsweep::report
