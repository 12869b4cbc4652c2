#include "report/html/metric_plot_plan.h"

#include <cstddef>
#include <string>

#include "report/html/view_pages.h"

namespace slamsweep::report::inline html {
namespace {

namespace fs = std::filesystem;

struct PlotSpec {
  const MetricColumn* column;
  std::size_t index;
  bool trajectory;
};

}  // namespace

std::vector<PlotRequest> PlanPlots(const SweepModel& model, const ReportLayout& layout, const fs::path& out_dir,
                                   SiteData& site) {
  std::vector<PlotRequest> requests;
  for (const SequenceModel& sequence : model.sequences) {
    std::vector<PlotSpec> specs;
    for (std::size_t c = 0; c < sequence.trajectory_columns.size(); ++c) {
      if (sequence.trajectory_columns[c].metric == "ape_trans")
        specs.push_back({&sequence.trajectory_columns[c], c, true});
    }
    for (std::size_t c = 0; c < sequence.map_columns.size(); ++c) specs.push_back({&sequence.map_columns[c], c, false});
    for (const PlotSpec& spec : specs) {
      const MetricColumn& column = *spec.column;
      std::size_t row_index = 0;
      PlotRequest request;
      request.title = sequence.title + ": " + column.title + (column.spec.empty() ? "" : ", " + column.spec);
      request.y_label = column.title + (column.unit.empty() ? "" : " (" + column.unit + ")");
      request.log_scale = true;
      for (const AlgorithmRow& row : sequence.rows) {
        const MetricCell& cell = spec.trajectory ? row.trajectory_cells[spec.index] : row.map_cells[spec.index];
        if (!cell.values.empty())
          request.series.push_back({row.algorithm, cell.values, RowStyle(site, sequence, row_index)});
        ++row_index;
      }
      if (request.series.empty()) continue;
      PlotArtifact artifact;
      artifact.metric = column.metric;
      artifact.title = request.title;
      artifact.path = layout.Plot(sequence.key, column.metric + (column.spec.empty() ? "" : "-" + column.spec));
      artifact.note = "no image maker configured";
      request.png = out_dir / artifact.path;
      site.plots[sequence.key].push_back(artifact);
      requests.push_back(std::move(request));
    }
  }
  return requests;
}

}  // namespace slamsweep::report::inline html
