#include "orchestrator/run/run_record.h"

namespace slamsweep::orchestrator {

std::optional<double> RunRecord::Metric(std::string_view metric_name, std::string_view statistic) const {
  for (const FlatMetric& m : metrics) {
    if (m.metric == metric_name && m.statistic == statistic) return m.value;
  }
  return std::nullopt;
}

std::string RunRecord::MetricUnit(std::string_view metric_name, std::string_view statistic) const {
  for (const FlatMetric& m : metrics) {
    if (m.metric == metric_name && m.statistic == statistic) return m.unit;
  }
  return {};
}

}  // namespace slamsweep::orchestrator
