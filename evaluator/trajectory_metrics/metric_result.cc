#include "evaluator/trajectory_metrics/metric_result.h"

namespace slamsweep::evaluator::inline trajectory_metrics {

nlohmann::json MetricResult::ToJson() const {
  nlohmann::json out = statistics;
  out["metric"] = metric;
  out["unit"] = unit;
  out["specification"] = specification;
  out["pairs"] = pairs;
  out["reference_unpaired"] = reference_unpaired;
  out["estimate_unpaired"] = estimate_unpaired;
  if (alignment) out["alignment"] = evaluator::ToJson(*alignment);
  return out;
}

void FinishMetricResult(std::string metric, PoseRelation pose_relation, nlohmann::json specification,
                        const AssociatedIndices& pairs, MetricResult& result) {
  result.metric = std::move(metric);
  result.unit = std::string(PoseRelationUnit(pose_relation));
  result.specification = std::move(specification);
  result.statistics = ComputeStatistics(result.errors);
  result.pairs = pairs.size();
  result.reference_unpaired = pairs.reference_unpaired;
  result.estimate_unpaired = pairs.estimate_unpaired;
}

}  // namespace slamsweep::evaluator::inline trajectory_metrics
