#include "orchestrator/run/flat_metric.h"

namespace slamsweep::orchestrator::inline run {

nlohmann::json ToJson(const FlatMetric& metric) {
  return {{"metric", metric.metric},
          {"statistic", metric.statistic},
          {"value", metric.value ? nlohmann::json(*metric.value) : nlohmann::json(nullptr)},
          {"unit", metric.unit}};
}

}  // namespace slamsweep::orchestrator::inline run
