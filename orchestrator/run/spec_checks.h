#pragma once

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline run {

/// Range checks shared by the sweep config and run.json: InputError naming `path`.field and what is
/// expected ("evaluation.rpe_delta_m: expected a finite distance > 0 m"), without a file location
/// (the caller adds it).
void ValidateEvaluationOptions(const EvaluationOptions& evaluation, const std::string& path);
void ValidateThreshold(const Threshold& threshold, const std::string& path);

/// `evaluation.rpe_segments_m` as written (YAML converted to JSON, or run.json): "auto" (nullopt) or a
/// list of distinct lengths > 0 m, returned ascending. InputError naming `path` otherwise.
std::optional<std::vector<double>> ParseSegmentLengths(const nlohmann::json& value, const std::string& path);
/// "auto" or the list, as ParseSegmentLengths reads it back.
nlohmann::json SegmentLengthsJson(const std::optional<std::vector<double>>& lengths_m);

/// The fields of an `evaluation:` block, read through either reader of strict fields (YAML in the
/// sweep file, JSON in run.json): both offer Text, Number and Unsigned with a fallback.
template <typename Fields>
void ReadEvaluationFields(Fields& fields, EvaluationOptions& evaluation) {
  evaluation.align = fields.Text("align", evaluation.align);
  evaluation.rpe_delta_m = fields.Number("rpe_delta_m", evaluation.rpe_delta_m);
  evaluation.t_max_diff_s = fields.Number("t_max_diff_s", evaluation.t_max_diff_s);
  evaluation.stages = fields.Unsigned("stages", evaluation.stages);
  evaluation.map_resolution_m = fields.Number("map_resolution_m", evaluation.map_resolution_m);
  evaluation.crop = fields.Bool("crop", evaluation.crop);
  evaluation.min_coverage = fields.Number("min_coverage", evaluation.min_coverage);
}

/// Whether `value` is one of a fixed list of names, and the list for "expected ..." messages.
template <std::size_t N>
bool OneOf(const std::string& value, const std::string_view (&choices)[N]) {
  return std::find(std::begin(choices), std::end(choices), value) != std::end(choices);
}

template <std::size_t N>
std::string Choices(const std::string_view (&choices)[N]) {
  std::string text;
  for (std::size_t i = 0; i < N; ++i) text += (i == 0 ? "" : i + 1 == N ? " or " : ", ") + std::string(choices[i]);
  return text;
}

}  // namespace slamsweep::orchestrator::inline run
