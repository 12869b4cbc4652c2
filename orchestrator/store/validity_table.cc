#include "orchestrator/store/validity_table.h"

namespace slamsweep::orchestrator::inline store {

evaluator::ValidityRun ToValidityRun(const RunRecord& run) {
  evaluator::ValidityRun out;
  out.run_id = run.run_id;
  out.sequence = run.sequence;
  out.noise = run.noise;
  out.algorithm = run.algorithm;
  out.ok = run.status == RunStatus::kOk;
  out.odometry_is_reference = run.odometry_is_reference;
  for (const FlatMetric& metric : run.metrics) {
    if (metric.value) out.values[metric.metric + "." + metric.statistic] = *metric.value;
  }
  if (!run.command.empty()) {
    for (const auto& [key, value] :
         {std::pair{"wall_s", run.wall_s}, {"cpu_s", run.cpu_s}, {"peak_rss_kb", run.peak_rss_kb}}) {
      if (value) out.values[key] = *value;
    }
  }
  return out;
}

std::vector<evaluator::ValidityRun> ToValidityRuns(const std::vector<RunRecord>& runs) {
  std::vector<evaluator::ValidityRun> converted;
  converted.reserve(runs.size());
  for (const RunRecord& run : runs) converted.push_back(ToValidityRun(run));
  return converted;
}

evaluator::ValidityStudy ValidityStudyOf(const std::vector<RunRecord>& runs) {
  return evaluator::ComputeValidityStudy(ToValidityRuns(runs));
}

}  // namespace slamsweep::orchestrator::inline store
