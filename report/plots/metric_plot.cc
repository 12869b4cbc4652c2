#include "report/plots/metric_plot.h"

#include "report/plots/metric_plot_script.h"
#include "report/plots/plot_batch.h"

namespace slamsweep::report {

void WriteMetricPlots(const std::vector<MetricPlotJob>& jobs) {
  std::vector<PlotScript> scripts;
  scripts.reserve(jobs.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    scripts.push_back({jobs[i].plot.title, jobs[i].png, MetricPlotScript(jobs[i].plot, jobs[i].png, i)});
  }
  DrawPlotScripts(scripts);
}

}  // namespace slamsweep::report
