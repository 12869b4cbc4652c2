#include "report/plots/view_figures.h"

#include "report/plots/gnuplot_batch.h"
#include "report/plots/view_figure_scripts.h"

namespace slamsweep::report::inline plots {

void WriteViewFigures(const std::vector<FigureJob>& jobs) {
  RunGnuplotJobs(jobs, [](const FigureJob& job, std::size_t i) {
    return GnuplotBatchJob{FigureScript(job, i), job.png, FigureTitle(job.figure)};
  });
}

}  // namespace slamsweep::report::inline plots
