#include "orchestrator/store/validity_table.h"

namespace slamsweep::orchestrator {

evaluator::ValidityRun ToValidityRun(const StoredRun& run) {
  evaluator::ValidityRun out;
  out.run_id = run.run_id;
  out.sequence = run.sequence;
  out.noise = run.noise;
  out.algorithm = run.algorithm;
  out.ok = run.status == RunStatus::kOk;
  out.odometry_is_reference = run.odometry_is_reference;
  for (const StoredMetric& metric : run.metrics) {
    if (metric.value) out.values[metric.metric + "." + metric.statistic] = *metric.value;
  }
  const auto command = run.result.find("command");
  const bool ran_a_program = command != run.result.end() && command->is_array() && !command->empty();
  if (ran_a_program) {
    for (const char* resource : {"wall_s", "cpu_s", "peak_rss_kb"}) {
      const auto value = run.result.find(resource);
      if (value != run.result.end() && value->is_number()) out.values[resource] = value->get<double>();
    }
  }
  return out;
}

evaluator::ValidityStudy ValidityStudyOf(const std::vector<StoredRun>& runs) {
  std::vector<evaluator::ValidityRun> converted;
  converted.reserve(runs.size());
  for (const StoredRun& run : runs) converted.push_back(ToValidityRun(run));
  return evaluator::ComputeValidityStudy(std::move(converted));
}

}  // namespace slamsweep::orchestrator
