#include "report/plots/metric_plot.h"

#include "report/plots/gnuplot_batch.h"
#include "report/plots/metric_plot_script.h"

namespace slamsweep::report {

void WriteMetricPlots(const std::vector<MetricPlotJob>& jobs) {
  std::vector<GnuplotBatchJob> batch;
  batch.reserve(jobs.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    batch.push_back({MetricPlotScript(jobs[i].plot, jobs[i].png, i), jobs[i].png, jobs[i].plot.title});
  }
  RunGnuplotBatch(batch);
}

}  // namespace slamsweep::report
