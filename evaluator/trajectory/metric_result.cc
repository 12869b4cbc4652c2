#include "evaluator/trajectory/metric_result.h"

namespace slamsweep::evaluator {

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

}  // namespace slamsweep::evaluator
