#include "orchestrator/run/spec_checks.h"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator::inline run {
namespace {

using evaluator::InputError;

std::string Field(const std::string& path, std::string_view key) { return path + "." + std::string(key); }

}  // namespace

void ValidateEvaluationOptions(const EvaluationOptions& evaluation, const std::string& path) {
  constexpr std::string_view kAlignments[] = {"none", "origin", "se2", "se3", "sim2", "sim3"};
  if (std::find(std::begin(kAlignments), std::end(kAlignments), evaluation.align) == std::end(kAlignments)) {
    throw InputError(Field(path, "align") + ": expected none, origin, se2, se3, sim2 or sim3, got \"" +
                     evaluation.align + "\"");
  }
  if (!(evaluation.rpe_delta_m > 0.0) || !std::isfinite(evaluation.rpe_delta_m)) {
    throw InputError(Field(path, "rpe_delta_m") + ": expected a finite distance > 0 m");
  }
  if (!(evaluation.t_max_diff_s >= 0.0) || !std::isfinite(evaluation.t_max_diff_s)) {
    throw InputError(Field(path, "t_max_diff_s") + ": expected a finite time >= 0 s");
  }
  if (!(evaluation.map_resolution_m > 0.0) || !std::isfinite(evaluation.map_resolution_m)) {
    throw InputError(Field(path, "map_resolution_m") + ": expected a finite cell size > 0 m");
  }
  if (!(evaluation.min_coverage >= 0.0 && evaluation.min_coverage <= 1.0)) {
    throw InputError(Field(path, "min_coverage") + ": expected a fraction of the reference's time span in [0, 1]");
  }
}

std::optional<std::vector<double>> ParseSegmentLengths(const nlohmann::json& value, const std::string& path) {
  constexpr std::string_view kExpected =
      "expected auto or a list of distinct segment lengths > 0 m such as [5, 10, 20]";
  if (value.is_string() && value.get<std::string>() == "auto") return std::nullopt;
  if (!value.is_array()) throw InputError(path + ": " + std::string(kExpected) + ", got " + value.dump());
  std::vector<double> lengths;
  for (const nlohmann::json& item : value) {
    if (!item.is_number() || !std::isfinite(item.get<double>()) || item.get<double>() <= 0.0 ||
        std::find(lengths.begin(), lengths.end(), item.get<double>()) != lengths.end()) {
      throw InputError(path + ": " + std::string(kExpected) + ", got " + value.dump());
    }
    lengths.push_back(item.get<double>());
  }
  std::sort(lengths.begin(), lengths.end());
  return lengths;
}

nlohmann::json SegmentLengthsJson(const std::optional<std::vector<double>>& lengths_m) {
  return lengths_m ? nlohmann::json(*lengths_m) : nlohmann::json("auto");
}

void ValidateThreshold(const Threshold& threshold, const std::string& path) {
  if (threshold.metric.empty()) throw InputError(Field(path, "metric") + ": expected a metric name such as ape_trans");
  if (threshold.statistic.empty()) throw InputError(Field(path, "statistic") + ": expected a statistic such as rmse");
  if (!threshold.max && !threshold.min) throw InputError(path + ": expected a limit: max, min or both");
  if ((threshold.max && !std::isfinite(*threshold.max)) || (threshold.min && !std::isfinite(*threshold.min))) {
    throw InputError(path + ": expected finite limits");
  }
}

}  // namespace slamsweep::orchestrator::inline run
