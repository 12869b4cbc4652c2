#pragma once

#include <cstddef>
#include <span>

#include <nlohmann/json.hpp>

namespace slamsweep::evaluator::inline core {

/// Summary of one error vector, as evo reports it: std is the population standard
/// deviation (ddof = 0) and the median of an even count is the mean of the middle two.
struct ErrorStatistics {
  double rmse = 0.0;
  double mean = 0.0;
  double median = 0.0;
  double std = 0.0;
  double min = 0.0;
  double max = 0.0;
  double sse = 0.0;
  std::size_t n = 0;
};

/// Throws InputError on an empty vector: a statistic of nothing is not a number.
ErrorStatistics ComputeStatistics(std::span<const double> errors);

void to_json(nlohmann::json& out, const ErrorStatistics& statistics);
void from_json(const nlohmann::json& in, ErrorStatistics& statistics);

}  // namespace slamsweep::evaluator::inline core
