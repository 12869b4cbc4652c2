#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace slamsweep::orchestrator::inline run {

/// One number of result.json's flat `metrics` list (orchestrator/DESIGN.md), e.g. {"ape_trans", "rmse", 0.12, "m"}.
struct FlatMetric {
  std::string metric;     ///< "ape_trans", "rpe_rot", "relations_trans", "corners", ...
  std::string statistic;  ///< "rmse", "mean", ..., "n", or "value" for the map metrics
  /// Empty: the worker wrote null (a statistic that is not a number).
  std::optional<double> value;
  std::string unit;  ///< "m", "deg", "ratio", "count"
};

/// {"metric", "statistic", "value", "unit"}; a missing value is null.
nlohmann::json ToJson(const FlatMetric& metric);

}  // namespace slamsweep::orchestrator::inline run
