#include "report/plots/metric_plot.h"

#include "report/plots/gnuplot_batch.h"
#include "report/plots/metric_plot_script.h"

namespace slamsweep::report::inline plots {

void WriteMetricPlots(const std::vector<MetricPlotJob>& jobs) {
  RunGnuplotJobs(jobs, [](const MetricPlotJob& job, std::size_t i) {
    return GnuplotBatchJob{MetricPlotScript(job.plot, job.png, i), job.png, job.plot.title};
  });
}

}  // namespace slamsweep::report::inline plots
